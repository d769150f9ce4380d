// The sun's disc in the sky's background on the GPU (llvmpipe in CI): each pixel shows the share
// of its solid angle the disc covers (pixel_shading.glsl's sunDiscCover), so the sun's light in
// the image, Σ Y·Ω over the pixels, does not depend on the image's size. Seen through each
// pixel's centre alone, a sun smaller than a pixel was in some sizes and not in others: sunset's
// mean Y 1 411 cd/m² at 160×90, 16 840 at 320×180.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <vector>

#include "gpu/headless_context.h"
#include "render/gbuffer_readback_test_support.h"
#include "render/renderer.h"
#include "scene/scene_loader.h"
#include "spectral/table_test_support.h"

namespace prism::render {
namespace {

// The direction through image point uv ∈ [0, 1]² (GL rows: 0 at the bottom).
glm::dvec3 directionAt(const CameraTransform& c, double u, double v) {
  const glm::dvec4 p = glm::inverse(glm::dmat4(c.viewProjection)) * glm::dvec4(2.0 * u - 1.0, 2.0 * v - 1.0, 1.0, 1.0);
  return glm::normalize(glm::dvec3(p) / p.w - glm::dvec3(c.position));
}

// Σ Y·Ω over the image (cd/m² · sr): the pixels' luminance times their exact solid angles
// (two triangles between the corners' directions, by the Van Oosterom–Strackee formula).
double luminousIntensitySum(const Renderer& renderer, int w, int h) {
  const GBufferReadback g(renderer);
  const CameraTransform& c = renderer.cameraTransform();
  auto triangle = [](const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& d) {
    return 2.0 * std::atan2(std::abs(glm::dot(a, glm::cross(b, d))), 1.0 + glm::dot(a, b) + glm::dot(b, d) + glm::dot(d, a));
  };
  double sum = 0.0;
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const double u0 = double(x) / w, u1 = double(x + 1) / w, v0 = double(y) / h, v1 = double(y + 1) / h;
      const glm::dvec3 a = directionAt(c, u0, v0), b = directionAt(c, u1, v0), d = directionAt(c, u1, v1),
                       e = directionAt(c, u0, v1);
      const double omega = triangle(a, b, d) + triangle(a, d, e);
      sum += g.accumulated(static_cast<std::size_t>(y * w + x)).y * omega;
    }
  return sum;
}

TEST(SunDisc, ItsLightInTheImageDoesNotDependOnTheImagesSize) {
  gpu::HeadlessContext context;
  const Scene scene = loadScene(std::filesystem::path(PRISM_SCENES_DIR) / "sunset.json");
  std::vector<double> sums;
  for (int w : {96, 160, 320}) {
    FrameSettings s;
    s.width = w;
    s.height = w * 9 / 16;
    s.mode = RenderMode::Rgb;
    s.shadowMapSize = 256;
    Renderer renderer(scene, cachedTestTable(), s);
    renderer.renderFrame();
    sums.push_back(luminousIntensitySum(renderer, s.width, s.height));
    std::printf("sunset at %dx%d: sum of Y times solid angle %.6g cd/m2 sr\n", s.width, s.height, sums.back());
  }
  const auto [lo, hi] = std::minmax_element(sums.begin(), sums.end());
  EXPECT_LT(*hi / *lo, 1.02);
}

}  // namespace
}  // namespace prism::render
