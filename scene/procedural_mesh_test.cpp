#include "scene/procedural_mesh.h"

#include <gtest/gtest.h>

#include <cmath>

namespace prism {
namespace {

// Every triangle is counter-clockwise seen from outside: its geometric normal agrees with the
// vertex normals and, for a convex mesh, points away from the centre.
void expectOutwardCcw(const Mesh& mesh, const glm::vec3& centre) {
  ASSERT_EQ(mesh.indices.size() % 3, 0u);
  for (std::size_t i = 0; i < mesh.indices.size(); i += 3) {
    const Vertex &a = mesh.vertices[mesh.indices[i]], &b = mesh.vertices[mesh.indices[i + 1]],
                 &c = mesh.vertices[mesh.indices[i + 2]];
    glm::vec3 face = glm::cross(b.position - a.position, c.position - a.position);
    ASSERT_GT(glm::length(face), 0.0f) << "degenerate triangle " << i / 3;
    glm::vec3 centroid = (a.position + b.position + c.position) / 3.0f;
    EXPECT_GT(glm::dot(face, centroid - centre), 0.0f) << "triangle " << i / 3;
    EXPECT_GT(glm::dot(face, a.normal + b.normal + c.normal), 0.0f) << "triangle " << i / 3;
  }
}

// Unit tangents orthogonal to unit normals, w = ±1.
void expectOrthonormalFrames(const Mesh& mesh) {
  for (const Vertex& v : mesh.vertices) {
    EXPECT_NEAR(glm::length(v.normal), 1.0f, 1e-5f);
    EXPECT_NEAR(glm::length(glm::vec3(v.tangent)), 1.0f, 1e-5f);
    EXPECT_NEAR(glm::dot(v.normal, glm::vec3(v.tangent)), 0.0f, 1e-5f);
    EXPECT_EQ(std::abs(v.tangent.w), 1.0f);
  }
}

TEST(ProceduralMesh, SphereNormalsAreUnitAndPointOutward) {
  glm::vec3 centre(1.0f, 2.0f, -3.0f);
  Mesh sphere = makeSphere(centre, 0.5f, 24);
  EXPECT_EQ(sphere.vertices.size(), 25u * 13u);
  EXPECT_EQ(sphere.indices.size(), 3u * 24u * (2u * 12u - 2u));  // no triangles at the poles' rows twice
  for (const Vertex& v : sphere.vertices) {
    EXPECT_NEAR(glm::length(v.normal), 1.0f, 1e-6f);
    glm::vec3 radial = (v.position - centre) / 0.5f;
    EXPECT_NEAR(glm::length(radial), 1.0f, 1e-5f);
    EXPECT_GT(glm::dot(v.normal, radial), 0.99999f);
  }
  expectOutwardCcw(sphere, centre);
  expectOrthonormalFrames(sphere);
}

TEST(ProceduralMesh, SphereTangentsFollowTheUvConvention) {
  Mesh sphere = makeSphere(glm::vec3(0.0f), 1.0f, 32);
  Mesh computed = sphere;
  computeTangents(computed);
  for (std::size_t i = 0; i < sphere.vertices.size(); ++i) {
    const Vertex& v = sphere.vertices[i];
    if (std::abs(v.normal.y) > 0.95f) continue;  // near the poles the uv map pinches
    EXPECT_GT(glm::dot(glm::vec3(v.tangent), glm::vec3(computed.vertices[i].tangent)), 0.99f) << i;
    EXPECT_EQ(v.tangent.w, computed.vertices[i].tangent.w) << i;
    // The bitangent points toward the north pole, which is up (−v) in the image.
    glm::vec3 bitangent = glm::cross(v.normal, glm::vec3(v.tangent)) * v.tangent.w;
    EXPECT_GT(bitangent.y, 0.0f) << i;
  }
}

TEST(ProceduralMesh, PlaneFacesItsNormal) {
  Mesh floor = makePlane(glm::vec3(0.0f, -1.0f, 0.0f), glm::vec3(0.0f, 3.0f, 0.0f), glm::vec2(4.0f, 2.0f));
  ASSERT_EQ(floor.vertices.size(), 4u);
  expectOutwardCcw(floor, glm::vec3(0.0f, -2.0f, 0.0f));
  expectOrthonormalFrames(floor);
  for (const Vertex& v : floor.vertices) {
    EXPECT_EQ(v.normal, glm::vec3(0.0f, 1.0f, 0.0f));
    EXPECT_EQ(std::abs(v.position.x), 2.0f);  // width along +x for a floor
    EXPECT_EQ(std::abs(v.position.z), 1.0f);
  }
  Mesh computed = floor;
  computeTangents(computed);
  for (std::size_t i = 0; i < 4; ++i) EXPECT_EQ(computed.vertices[i].tangent, floor.vertices[i].tangent);
  Mesh tilted = makePlane(glm::vec3(0.0f), glm::vec3(1.0f, 1.0f, -1.0f), glm::vec2(1.0f));
  expectOutwardCcw(tilted, -glm::normalize(glm::vec3(1.0f, 1.0f, -1.0f)));
  expectOrthonormalFrames(tilted);
}

TEST(ProceduralMesh, BoxFacesOutwardWhenRotated) {
  glm::vec3 centre(2.0f, 0.5f, 0.0f);
  Mesh box = makeBox(centre, glm::vec3(1.0f, 2.0f, 3.0f), glm::vec3(10.0f, 45.0f, -30.0f));
  EXPECT_EQ(box.vertices.size(), 24u);
  EXPECT_EQ(box.indices.size(), 36u);
  expectOutwardCcw(box, centre);
  expectOrthonormalFrames(box);
  for (const Vertex& v : box.vertices) EXPECT_NEAR(glm::length(v.position - centre), std::sqrt(0.25f + 1.0f + 2.25f), 1e-5f);
}

TEST(ProceduralMesh, EulerRotationIsXThenYThenZ) {
  glm::mat3 r = eulerRotation(glm::vec3(90.0f, 90.0f, 0.0f));
  // +y → (x 90°) +z → (y 90°) +x.
  glm::vec3 v = r * glm::vec3(0.0f, 1.0f, 0.0f);
  EXPECT_NEAR(v.x, 1.0f, 1e-6f);
  EXPECT_NEAR(v.y, 0.0f, 1e-6f);
  EXPECT_NEAR(v.z, 0.0f, 1e-6f);
}

TEST(ProceduralMesh, ComputedNormalsAreAreaWeightedAndUnit) {
  Mesh sphere = makeSphere(glm::vec3(0.0f), 2.0f, 48);
  Mesh computed = sphere;
  computeNormals(computed);
  std::vector<bool> used(sphere.vertices.size(), false);
  for (std::uint32_t index : sphere.indices) used[index] = true;
  for (std::size_t i = 0; i < sphere.vertices.size(); ++i) {
    EXPECT_NEAR(glm::length(computed.vertices[i].normal), 1.0f, 1e-5f);
    if (!used[i]) continue;  // one copy of each pole closes no triangle: +y by definition
    // Where a vertex's fan is one-sided (the poles, repeated once per slice, and the u seam)
    // the area-weighted normal tilts by up to half a slice or stack, 3.75° at 48 segments.
    EXPECT_GT(glm::dot(sphere.vertices[i].normal, computed.vertices[i].normal), std::cos(glm::radians(4.0f))) << i;
  }
}

}  // namespace
}  // namespace prism

namespace prism {
namespace {

TEST(ProceduralMesh, HeightFieldFacesUpStaysWithinItsAmplitudeAndRepeatsItsSeed) {
  Mesh field = makeHeightField({1.0f, -2.0f, 3.0f}, {8.0f, 6.0f}, 16, 0.5f, 2.0f, 7, 2.0f);
  ASSERT_EQ(field.vertices.size(), 17u * 17u);
  ASSERT_EQ(field.indices.size(), 16u * 16u * 6u);
  float lowest = 1e9f, highest = -1e9f;
  for (const Vertex& v : field.vertices) {
    lowest = std::min(lowest, v.position.y);
    highest = std::max(highest, v.position.y);
    EXPECT_GT(v.normal.y, 0.0f);
    EXPECT_NEAR(glm::length(v.normal), 1.0f, 1e-5f);
  }
  EXPECT_GE(lowest, -2.5f);
  EXPECT_LE(highest, -1.5f);
  EXPECT_GT(highest - lowest, 0.2f) << "not flat";
  for (std::size_t t = 0; t < field.indices.size(); t += 3) {
    const glm::vec3& a = field.vertices[field.indices[t]].position;
    const glm::vec3& b = field.vertices[field.indices[t + 1]].position;
    const glm::vec3& c = field.vertices[field.indices[t + 2]].position;
    EXPECT_GT(glm::cross(b - a, c - a).y, 0.0f) << "triangle " << t / 3 << " faces down";
  }
  EXPECT_FLOAT_EQ(field.vertices.back().uv.x, (1.0f + 4.0f) / 2.0f);  // x / tile at the far corner
  Mesh again = makeHeightField({1.0f, -2.0f, 3.0f}, {8.0f, 6.0f}, 16, 0.5f, 2.0f, 7, 2.0f);
  EXPECT_EQ(again.vertices[100].position, field.vertices[100].position);
  Mesh other = makeHeightField({1.0f, -2.0f, 3.0f}, {8.0f, 6.0f}, 16, 0.5f, 2.0f, 8, 2.0f);
  EXPECT_NE(other.vertices[100].position, field.vertices[100].position);
}

}  // namespace
}  // namespace prism
