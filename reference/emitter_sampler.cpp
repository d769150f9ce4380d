#include "reference/emitter_sampler.h"

#include <algorithm>
#include <cmath>

#include "core/error.h"

namespace prism::reference {
namespace {

// What a material emits, as far as choosing between emitters goes: its luminance in cd/m² (0
// where it emits nothing).
double emittedLuminance(const Material& m) {
  if (m.emission) return std::max(0.0, static_cast<double>(m.emission->luminance));
  if (m.emitsRgb())
    return static_cast<double>(m.emissiveLuminance) *
           std::max({m.emissiveFactor.r, m.emissiveFactor.g, m.emissiveFactor.b});
  return 0.0;
}

glm::vec3 corner(const Mesh& mesh, std::uint32_t triangle, int k) {
  return mesh.vertices[mesh.indices[3 * triangle + static_cast<std::uint32_t>(k)]].position;
}

}  // namespace

EmitterSampler::EmitterSampler(const Scene& scene) : mScene(scene), mPdfArea(scene.meshes.size(), 0.0f) {
  double sum = 0.0;
  std::vector<double> meshLuminance(scene.meshes.size(), 0.0);
  for (std::size_t m = 0; m < scene.meshes.size(); ++m) {
    const Mesh& mesh = scene.meshes[m];
    const double luminance = emittedLuminance(scene.materials[static_cast<std::size_t>(mesh.material)]);
    if (!(luminance > 0.0)) continue;
    meshLuminance[m] = luminance;
    for (std::uint32_t t = 0; 3 * t + 2 < mesh.indices.size(); ++t) {
      const glm::vec3 a = corner(mesh, t, 0), b = corner(mesh, t, 1), c = corner(mesh, t, 2);
      const double area = 0.5 * static_cast<double>(glm::length(glm::cross(b - a, c - a)));
      if (!(area > 0.0)) continue;
      sum += area * luminance;
      mTriangles.push_back({static_cast<std::uint32_t>(m), t});
      mCumulative.push_back(sum);
    }
  }
  if (!(sum > 0.0)) {
    mTriangles.clear();
    mCumulative.clear();
    return;
  }
  // A point of mesh m is drawn with density luminance_m / Σ area·luminance per m².
  for (std::size_t m = 0; m < scene.meshes.size(); ++m) mPdfArea[m] = static_cast<float>(meshLuminance[m] / sum);
}

EmitterPoint EmitterSampler::sample(double u0, float u1, float u2) const {
  PRISM_CHECK(!empty());
  const double target = u0 * mCumulative.back();
  const std::size_t i = std::min<std::size_t>(
      static_cast<std::size_t>(std::upper_bound(mCumulative.begin(), mCumulative.end(), target) - mCumulative.begin()),
      mTriangles.size() - 1);
  const Triangle& chosen = mTriangles[i];
  const Mesh& mesh = mScene.meshes[chosen.geometry];
  const glm::vec3 a = corner(mesh, chosen.triangle, 0), b = corner(mesh, chosen.triangle, 1),
                  c = corner(mesh, chosen.triangle, 2);
  // Uniform on the triangle: p = (1 − √u1)·a + √u1·(1 − u2)·b + √u1·u2·c.
  const float root = std::sqrt(u1);
  EmitterPoint point;
  point.at.geometry = chosen.geometry;
  point.at.triangle = chosen.triangle;
  point.at.u = root * (1.0f - u2);
  point.at.v = root * u2;
  point.position = (1.0f - point.at.u - point.at.v) * a + point.at.u * b + point.at.v * c;
  point.normal = glm::normalize(glm::cross(b - a, c - a));
  point.pdfArea = mPdfArea[chosen.geometry];
  return point;
}

}  // namespace prism::reference
