// Emitting materials on the GPU (llvmpipe in CI), held to their own spectra: every pixel of an
// emitter that reflects nothing (black and Lambertian) shows the emission's luminance and
// chromaticity, the 1 nm integral of the scene's spectrum, in the reference, RGB and spectral
// modes; glTF's emission likewise, its colour upsampled as a light's. (The twin test holds the
// same fixtures' frames to the CPU, pixel by pixel.)
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "gpu/headless_context.h"
#include "render/gbuffer_readback_test_support.h"
#include "render/renderer.h"
#include "scene/scene_loader.h"
#include "spectral/colour_space.h"
#include "spectral/observer.h"
#include "spectral/rgb_intent.h"
#include "spectral/table_test_support.h"

namespace prism::render {
namespace {
namespace emitting {  // the target's files share one unity translation unit

glm::dvec2 chromaticity(const glm::dvec3& xyz) { return glm::dvec2(xyz.x, xyz.y) / (xyz.x + xyz.y + xyz.z); }

struct Worst {
  double luminance = 0.0;     // relative
  double chromaticity = 0.0;  // Δxy
  int pixels = 0;
};

// A frame's settings and the bounds its emitters' pixels are held to.
struct Case {
  const char* what;
  RenderMode mode;
  SamplingStrategy strategy;
  int frames;
  double luminance, chromaticity;  // the bounds: relative, Δxy
};

// RGB mode carries an emission's own tristimulus (float rounding); the reference mode's 472
// wavelengths are the 1 nm grid's midpoints.
const Case kRgbCase{"rgb", RenderMode::Rgb, SamplingStrategy::Uniform, 1, 1e-5, 1e-6};
const Case kReferenceCase{"reference", RenderMode::Reference, SamplingStrategy::Uniform, 1, 5e-3, 1e-3};

// The fixtures' frame: 160 × 90 (an emitter a few hundred pixels or more), small shadow maps.
FrameSettings smallFrame() {
  FrameSettings settings;
  settings.width = 160;
  settings.height = 90;
  settings.shadowMapSize = 256;
  return settings;
}

// Over the pixels of each black Lambertian emitter, the largest errors against its spectrum.
Worst worstEmitterPixel(const Scene& scene, const FrameSettings& settings, int frames) {
  Renderer renderer(scene, cachedTestTable(), settings);
  for (int f = 0; f < frames; ++f) renderer.renderFrame();
  const GBufferReadback frame(renderer);
  Worst worst;
  for (std::size_t i = 0; i < frame.ids.size(); ++i) {
    if (frame.ids[i] == 0) continue;  // the background
    const Material& m = scene.materials.at(frame.ids[i] - 1);
    if (!m.emission || !m.lambertian || m.baseColour != glm::vec3(0.0f)) continue;
    const Eigen::Vector3d truth = luminousTristimulus(m.emission->radiance());
    const glm::dvec3 expected(truth.x(), truth.y(), truth.z());
    const glm::dvec3 shown = glm::dvec3(frame.accumulated(i)) / static_cast<double>(frame.lit[4 * i + 3]);
    worst.luminance = std::max(worst.luminance, std::abs(shown.y / expected.y - 1.0));
    worst.chromaticity =
        std::max(worst.chromaticity, glm::length(chromaticity(shown) - chromaticity(expected)));
    ++worst.pixels;
  }
  return worst;
}

TEST(EmittingMaterials, ShowTheirOwnLuminanceAndChromaticity) {
  gpu::HeadlessContext context;
  const Scene scene = loadScene(std::filesystem::path(PRISM_RENDER_TEST_DIR) / "emitters.json");
  const auto tube = std::ranges::find(scene.materials, "tube", &Material::name);
  ASSERT_NE(tube, scene.materials.end());
  EXPECT_NEAR(luminousIntegral(tube->emission->radiance()), 400.0, 400.0 * 1e-12);  // as the file says
  FrameSettings settings = smallFrame();
  // 16 wavelengths a frame (the default count) drawn by the lights' pdf, which follows the
  // emitters too, converge on the F11 tube's lines as frames accumulate (as issue 16 holds lamps:
  // within 1 % in luminance and Δxy 1e-3 after 32 frames).
  for (const Case& c : {kRgbCase, kReferenceCase,
                        Case{"16 lights", RenderMode::JakobHanika, SamplingStrategy::Lights, 32, 0.01, 1e-3}}) {
    settings.mode = c.mode;
    settings.sampling.strategy = c.strategy;
    const Worst w = worstEmitterPixel(scene, settings, c.frames);
    std::printf("%-10s %5d emitter pixels: luminance %.2e, Δxy %.2e\n", c.what, w.pixels, w.luminance, w.chromaticity);
    EXPECT_GT(w.pixels, 500) << c.what;  // two spheres' discs, about 24 pixels across
    EXPECT_LE(w.luminance, c.luminance) << c.what;
    EXPECT_LE(w.chromaticity, c.chromaticity) << c.what;
  }
}

// An emitter that also reflects (the flame, grey) adds its emission to what it reflects: in RGB
// mode, its pixels less the same frame's without the emission are the emission's tristimulus.
TEST(EmittingMaterials, AddTheirEmissionToWhatTheyReflect) {
  gpu::HeadlessContext context;
  const Scene scene = loadScene(std::filesystem::path(PRISM_RENDER_TEST_DIR) / "emitters.json");
  Scene dark = scene;
  const auto flame = std::ranges::find(dark.materials, "flame", &Material::name);
  ASSERT_NE(flame, dark.materials.end());
  const Spectrum emission = flame->emission->radiance();
  flame->emission.reset();
  FrameSettings settings = smallFrame();
  settings.mode = RenderMode::Rgb;
  auto frame = [&](const Scene& s) {
    Renderer renderer(s, cachedTestTable(), settings);
    renderer.renderFrame();
    return GBufferReadback(renderer);
  };
  const GBufferReadback with = frame(scene), without = frame(dark);
  const Eigen::Vector3d truth = luminousTristimulus(emission);
  const auto flameId = static_cast<std::uint32_t>(flame - dark.materials.begin()) + 1;
  int pixels = 0, reflecting = 0;
  double worst = 0.0;
  for (std::size_t i = 0; i < with.ids.size(); ++i) {
    if (with.ids[i] != flameId) continue;
    const glm::dvec3 reflected(without.accumulated(i));
    const glm::dvec3 added = glm::dvec3(with.accumulated(i)) - reflected;
    for (int c = 0; c < 3; ++c) worst = std::max(worst, std::abs(added[c] / truth[c] - 1.0));
    reflecting += reflected.y > 0.05 * truth.y() ? 1 : 0;
    ++pixels;
  }
  std::printf("flame: %d pixels, %d reflecting more than 5 %% of its emission; emission added within %.2e\n", pixels,
              reflecting, worst);
  EXPECT_GT(reflecting, 100);
  EXPECT_LE(worst, 1e-5);  // float sums of a few tens of cd/m²
}

// glTF's emission (render/tests/emissive_gltf.json: two black panels in the dark, one of a flat
// colour, one textured) against the 1 nm integral of its colour upsampled as a light's
// (RgbIlluminantSpectrum) at each pixel's emissive colour as the G-buffer holds it: RGB mode
// against the colour's own tristimulus. A light's colour has a smooth spectrum, which the
// rotated grid integrates best (the lights' pdf, made for spiky lamps, leaves the texture's
// saturated reds Δxy 2.6e-3 off after 32 frames; README, "Emitting materials").
TEST(EmittingMaterials, GltfEmissionShowsItsColourAsALight) {
  gpu::HeadlessContext context;
  const Scene scene = loadScene(std::filesystem::path(PRISM_RENDER_TEST_DIR) / "emissive_gltf.json");
  const RgbColourSpace& space = colourSpace(scene.colourSpace);
  const auto glow = std::ranges::find(scene.materials, "emissive_panels.gltf/glow", &Material::name);
  ASSERT_NE(glow, scene.materials.end());
  EXPECT_EQ(glow->emissiveLuminance, 100.0f);  // the object's 50 cd/m² times the file's strength 2
  FrameSettings settings = smallFrame();  // no lights: the shadow maps' size does not matter
  for (const Case& c : {kRgbCase, kReferenceCase,  // the bounds as for the scene's own emitters above
                        Case{"16 rotated", RenderMode::JakobHanika, SamplingStrategy::Rotated, 32, 0.01, 1e-3}}) {
    settings.mode = c.mode;
    settings.sampling.strategy = c.strategy;
    Renderer renderer(scene, cachedTestTable(), settings);
    for (int f = 0; f < c.frames; ++f) renderer.renderFrame();
    const GBufferReadback frame(renderer);
    Worst worst;
    int textured = 0;
    for (std::size_t i = 0; i < frame.ids.size(); ++i) {
      if (frame.ids[i] == 0) continue;
      const Material& m = scene.materials.at(frame.ids[i] - 1);
      ASSERT_TRUE(m.emitsRgb());
      const glm::vec3 colour(frame.emission[4 * i], frame.emission[4 * i + 1], frame.emission[4 * i + 2]);
      const glm::dvec3 shown = glm::dvec3(frame.accumulated(i)) / static_cast<double>(frame.lit[4 * i + 3]);
      textured += m.emissiveTexture >= 0 ? 1 : 0;
      // The texture's black texel, filtered, is nowhere quite black.
      ASSERT_GT(std::max({colour.r, colour.g, colour.b}), 0.0f);
      Eigen::Vector3d truth;
      if (c.mode == RenderMode::Rgb) {
        truth = space.rgbToXyz * Eigen::Vector3d(colour.r, colour.g, colour.b) * static_cast<double>(m.emissiveLuminance);
      } else {
        truth = luminousTristimulus(
            RgbIlluminantSpectrum(cachedTestTable(), space, colour, m.emissiveLuminance).toDense());
      }
      const glm::dvec3 expected(truth.x(), truth.y(), truth.z());
      worst.luminance = std::max(worst.luminance, std::abs(shown.y / expected.y - 1.0));
      worst.chromaticity = std::max(worst.chromaticity, glm::length(chromaticity(shown) - chromaticity(expected)));
      ++worst.pixels;
    }
    std::printf("%-10s %5d emitting pixels (%d textured): luminance %.2e, Δxy %.2e\n", c.what, worst.pixels,
                textured, worst.luminance, worst.chromaticity);
    EXPECT_GT(worst.pixels, 8000) << c.what;  // two panels about 70 pixels a side
    EXPECT_GT(textured, 4000) << c.what;
    EXPECT_LE(worst.luminance, c.luminance) << c.what;
    EXPECT_LE(worst.chromaticity, c.chromaticity) << c.what;
  }
}

}  // namespace emitting
}  // namespace
}  // namespace prism::render
