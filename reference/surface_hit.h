// What the reference path tracer knows at a ray hit: the point, its geometric normal and the
// material's inputs there (shaders/shared/surface_inputs.glsl, the formula the G-buffer pass
// uses), with the scene's textures sampled on the CPU.
#pragma once

#include <glm/glm.hpp>

#include "rays/triangle_bvh.h"
#include "scene/scene.h"

namespace prism::reference {

struct SurfaceHit {
  glm::vec3 positionW{0.0f};
  glm::vec3 geometricNormalW{0.0f};  // unit, on the side the ray came from
  glm::vec3 albedo{0.0f};            // linear RGB, [0, 1]
  float metallic = 0.0f;
  float roughness = 0.0f;
  glm::vec3 normalW{0.0f};           // shading normal, unit, turned like the G-buffer's
  glm::vec2 uv{0.0f};                // interpolated texture coordinates
  glm::vec3 emission{0.0f};          // glTF's emissive colour (SurfaceInputs::emission)
  int material = 0;                  // index into Scene::materials
  // Diffuse lobe only (albedo/π): the material says so (the thesis's spheres), or a technique
  // shades the object itself (PRT's objects, diffuse by definition, lit by its environment).
  bool lambertian = false;
};

// `direction` is the unit direction of the ray that made `hit`. The shading normal is turned as
// the rasteriser turns it: flipped where the triangle's winding faces away from the ray
// (gl_FrontFacing false).
SurfaceHit surfaceHit(const Scene& scene, const rays::TriangleHit& hit, const glm::vec3& origin,
                      const glm::vec3& direction);

// Bilinear filtering with repeat wrapping at uv (glTF convention: v = 0 is the image's top row),
// texel centres at half-integers, as GL_LINEAR samples the base level. sRGB images are decoded
// per texel before filtering, as a GPU's sRGB texture is. RGBA in [0, 1].
glm::vec4 sampleTexture(const Image& image, const glm::vec2& uv);

}  // namespace prism::reference
