// The sun's disc in the sky's background on the GPU (llvmpipe in CI): each pixel shows the share
// of its solid angle the disc covers (pixel_shading.glsl's sunDiscCover), so the sun's light in
// the image, Σ Y·Ω over the pixels, does not depend on the image's size. Seen through each
// pixel's centre alone, a sun smaller than a pixel was in some sizes and not in others: sunset's
// mean Y 1 411 cd/m² at 160×90, 16 840 at 320×180. The disc's own part of that light is held
// too, so that an image without the disc (whose sky alone is the same at every size) fails.
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
#include "techniques/atmosphere/atmosphere_parameters.h"

namespace prism::render {
namespace {

// The direction through image point uv ∈ [0, 1]² (GL rows: 0 at the bottom).
glm::dvec3 directionAt(const CameraTransform& c, double u, double v) {
  const glm::dvec4 p = glm::inverse(glm::dmat4(c.viewProjection)) * glm::dvec4(2.0 * u - 1.0, 2.0 * v - 1.0, 1.0, 1.0);
  return glm::normalize(glm::dvec3(p) / p.w - glm::dvec3(c.position));
}

// The light of a sunset frame, Σ Y·Ω (cd/m² · sr): over the whole image, and the disc's own part
// of it, the pixels within a few pixels of the sun less what the sky around them would give there.
struct SunLight {
  double image = 0.0;
  double disc = 0.0;
  double skyUnderTheDisc = 0.0;  // the sky's estimate over the pixels the disc's part is taken from
};

// The pixels' luminance times their exact solid angles (two triangles between the corners'
// directions, by the Van Oosterom–Strackee formula). The disc's part: the pixels whose centres lie
// within the sun's radius plus three pixels' diagonals of the sun's direction, less the mean
// radiance of the ring of pixels three diagonals further out times their solid angle.
SunLight sunLight(const Renderer& renderer, int w, int h, const glm::dvec3& toSun) {
  const GBufferReadback g(renderer);
  const CameraTransform& c = renderer.cameraTransform();
  auto triangle = [](const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& d) {
    return 2.0 * std::atan2(std::abs(glm::dot(a, glm::cross(b, d))), 1.0 + glm::dot(a, b) + glm::dot(b, d) + glm::dot(d, a));
  };
  const double diagonal = std::acos(glm::dot(directionAt(c, 0.5, 0.5), directionAt(c, 0.5 + 1.0 / w, 0.5 + 1.0 / h)));
  const double near = atmosphere::AtmosphereParameters{}.sunAngularRadiusRad + 3.0 * diagonal;
  const double ring = near + 3.0 * diagonal;
  SunLight light;
  double nearOmega = 0.0, nearLight = 0.0, ringOmega = 0.0, ringLight = 0.0;
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const double u0 = double(x) / w, u1 = double(x + 1) / w, v0 = double(y) / h, v1 = double(y + 1) / h;
      const glm::dvec3 a = directionAt(c, u0, v0), b = directionAt(c, u1, v0), d = directionAt(c, u1, v1),
                       e = directionAt(c, u0, v1);
      const double omega = triangle(a, b, d) + triangle(a, d, e);
      const double yOmega = g.accumulated(static_cast<std::size_t>(y * w + x)).y * omega;
      light.image += yOmega;
      const double fromSun = std::acos(std::clamp(glm::dot(directionAt(c, u0 + 0.5 / w, v0 + 0.5 / h), toSun), -1.0, 1.0));
      if (fromSun <= near) {
        nearOmega += omega;
        nearLight += yOmega;
      } else if (fromSun <= ring) {
        ringOmega += omega;
        ringLight += yOmega;
      }
    }
  light.skyUnderTheDisc = ringLight / ringOmega * nearOmega;
  light.disc = nearLight - light.skyUnderTheDisc;
  return light;
}

TEST(SunDisc, ItsLightInTheImageDoesNotDependOnTheImagesSize) {
  gpu::HeadlessContext context;
  const Scene scene = loadScene(std::filesystem::path(PRISM_SCENES_DIR) / "sunset.json");
  const auto sun = std::find_if(scene.lights.begin(), scene.lights.end(),
                                [](const Light& l) { return l.technique == "atmosphere"; });
  ASSERT_NE(sun, scene.lights.end());
  const glm::dvec3 toSun = -glm::dvec3(sun->direction);
  std::vector<double> images, discs;
  for (int w : {96, 160, 320}) {
    FrameSettings s;
    s.width = w;
    s.height = w * 9 / 16;
    s.mode = RenderMode::Rgb;
    s.shadowMapSize = 256;
    Renderer renderer(scene, cachedTestTable(), s);
    renderer.renderFrame();
    const SunLight light = sunLight(renderer, s.width, s.height, toSun);
    images.push_back(light.image);
    discs.push_back(light.disc);
    std::printf("sunset at %dx%d: sum of Y times solid angle %.6g cd/m2 sr, the disc's %.6g (the sky under it %.3g)\n",
                s.width, s.height, light.image, light.disc, light.skyUnderTheDisc);
    // The disc outshines the sky it covers (a disc missing at this size leaves about nothing).
    EXPECT_GT(light.disc, 10.0 * light.skyUnderTheDisc);
  }
  const auto [lo, hi] = std::minmax_element(images.begin(), images.end());
  EXPECT_LT(*hi / *lo, 1.02);
  const auto [discLo, discHi] = std::minmax_element(discs.begin(), discs.end());
  EXPECT_LT(*discHi / *discLo, 1.02);
}

}  // namespace
}  // namespace prism::render
