// The reference path tracer's aim at emitting surfaces: every triangle of a mesh whose material
// emits (Material::emission, or glTF's emitsRgb), drawn with probability ∝ area × the
// material's luminance (glTF's: its emissive luminance × the factor's largest channel, the
// texture unknown), then a point uniform on it. So a small bright emitter lighting a room is
// found by next-event estimation, not only by a BRDF sample that happens to meet it; the path
// tracer weighs the two by multiple importance sampling.
#pragma once

#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "rays/triangle_bvh.h"
#include "scene/scene.h"

namespace prism::reference {

struct EmitterPoint {
  rays::TriangleHit at;       // geometry (mesh), triangle and barycentrics; distance left 0
  glm::vec3 position{0.0f};
  glm::vec3 normal{0.0f};     // unit, the triangle's winding's (emitters shine from both faces)
  float pdfArea = 0.0f;       // per m² of the scene's emitting area, this point's
};

class EmitterSampler {
 public:
  explicit EmitterSampler(const Scene& scene);

  bool empty() const { return mCumulative.empty(); }
  // A point drawn from three uniform numbers in [0, 1): u0 picks the triangle (so a double: a
  // triangle's share may be far below a float's 2⁻²⁴ step), u1 and u2 the point. PRISM_CHECKs !empty().
  EmitterPoint sample(double u0, float u1, float u2) const;
  // The density per area with which sample() draws a point of mesh `geometry` (0 where it emits
  // nothing): the same at every point of a mesh.
  float pdfArea(std::uint32_t geometry) const { return mPdfArea[geometry]; }

 private:
  struct Triangle {
    std::uint32_t geometry, triangle;
  };
  const Scene& mScene;
  std::vector<Triangle> mTriangles;  // the emitting ones, with a nonzero area
  std::vector<double> mCumulative;   // their running sum of area × luminance
  std::vector<float> mPdfArea;       // per mesh
};

}  // namespace prism::reference
