// Meshes made from a few numbers (the scene file's spheres, planes and boxes), and the mesh
// operations the glTF loader shares with them: normals, tangents, transforms.
//
// Conventions (those of glTF 2.0, which the renderer assumes for every mesh):
// - front faces are counter-clockwise seen from outside (from where the normal points);
// - uv (0, 0) is the top-left of an image, v grows downward;
// - tangent.xyz points along +u, and the bitangent cross(normal, tangent.xyz) · tangent.w
//   points along −v (up in the image): the normal-map convention of glTF's sample models,
//   whose tangents Blender computes with MikkTSpace before flipping v on export.
#pragma once

#include <cstdint>

#include <glm/glm.hpp>

#include "scene/scene.h"

namespace prism {

// A UV sphere: `segments` slices around the +y axis and segments/2 stacks (at least 2) from
// the north (+y) pole. u = longitude / 2π, starting at +z and growing toward +x; v = colatitude / π.
// Normals and tangents are analytic. segments ≥ 3.
Mesh makeSphere(const glm::vec3& centreW, float radiusM, int segments = 64);

// A rectangle of sizeM.x (along the tangent t) by sizeM.y (along b = normal × t), facing
// `normalW` (any length > 0). t is horizontal: normalize(+y × normal), or +x when the normal
// is vertical. The image's top edge lies toward +b; for a floor (normal +y) that is −z.
Mesh makePlane(const glm::vec3& centreW, const glm::vec3& normalW, const glm::vec2& sizeM);

// An axis-aligned box of sizeM, rotated by rotationDeg (eulerRotation) about its centre; each
// face is a makePlane quad (24 vertices, flat normals).
Mesh makeBox(const glm::vec3& centreW, const glm::vec3& sizeM, const glm::vec3& rotationDeg = {});

// A height field over sizeM.x (along +x) by sizeM.y (along +z) centred at centreW, a grid of
// resolution × resolution quads: y = centreW.y + amplitudeM · fbm(x/featureM, z/featureM), three
// octaves of value noise (lattice values from the PCG hash of random.glsl and `seed`, smoothstep
// interpolation, each octave half the size and half the height), in [−amplitude, amplitude].
// Front faces up; smooth normals and tangents computed; uv = (x, z) / tileM, so that a texture
// repeats every tileM metres (textures wrap). resolution ≥ 1, sizes, featureM and tileM > 0.
Mesh makeHeightField(const glm::vec3& centreW, const glm::vec2& sizeM, int resolution, float amplitudeM,
                     float featureM, std::uint32_t seed, float tileM);

// Rotation by Euler angles in degrees: about x first, then y, then z, all about the fixed
// (world) axes: R = Rz · Ry · Rx.
glm::mat3 eulerRotation(const glm::vec3& degrees);

// Translation · eulerRotation · scale, the scene file's object transform.
glm::mat4 trsMatrix(const glm::vec3& translation, const glm::vec3& rotationDeg,
                    const glm::vec3& scale);

// Applies a model → world transform: positions by m, normals by the normal matrix
// (transpose of the inverse), tangents by m's upper 3×3, both renormalised. A mirroring m
// (negative determinant) would turn front faces into back faces and flip the handedness, so
// then every triangle's winding is reversed and tangent.w negated.
void transformMesh(Mesh& mesh, const glm::mat4& m);

// Smooth vertex normals: the sum of the adjacent triangles' cross products (area-weighted),
// normalised; +y where that sum is zero.
void computeNormals(Mesh& mesh);
// computeNormals' normal for the vertices whose normal is zero (a glTF exporter's broken NORMAL:
// PRT's transfer turned its hemisphere about no axis, black below), the others kept.
void computeZeroNormals(Mesh& mesh);

// Tangents from positions, normals and uvs by per-triangle accumulation (Lengyel 2001,
// "Computing Tangent Space Basis Vectors for an Arbitrary Mesh"): ∂p/∂u summed over the
// adjacent triangles, made orthogonal to the normal (Gram–Schmidt); w from the side ∂p/∂v falls
// on (see the convention above). MikkTSpace differs in weighting and in splitting vertices at
// mirrored seams; on smooth, unmirrored uv layouts the two agree closely. Where uvs are
// degenerate, any unit vector orthogonal to the normal, with w = 1.
void computeTangents(Mesh& mesh);

}  // namespace prism
