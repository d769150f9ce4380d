// The nebula's pass in the renderer (llvmpipe in CI) against its CPU twin: the frame's mean
// tristimulus against NebulaRenderer::render from the same camera in the cube's coordinates,
// within the GPU marcher's twin bound (techniques/nebula/gpu/nebula_twin_test_support.h). The
// CIE 1931 filters at intensity 1 add the channels as they are, and nothing else lights the frame.
// With a wall through the middle of the cube the rays stop at it, as the CPU's do at the wall's
// analytic distance (RenderSettings::rayLimits).
#include "render/renderer.h"

#include <gtest/gtest.h>

#include <algorithm>

#include <cmath>
#include <cstdio>
#include <string>

#include <fmt/format.h>

#include "core/temp_file_test_support.h"
#include "core/worst_of.h"
#include "render/cpu_shading.h"
#include "render/gbuffer_readback_test_support.h"
#include "gpu/headless_context.h"
#include "scene/scene_loader.h"
#include "spectral/table_test_support.h"
#include "techniques/nebula/gpu/nebula_pass.h"
#include "techniques/nebula/gpu/nebula_twin_test_support.h"
#include "techniques/nebula/nebula_cpu_twin.h"

namespace prism::render {
namespace {

constexpr int kSize = 40;

// A 4 m cube of the twin tests' small nebula in front of a camera 4 m from it; `wall`: a black
// box whose face at z = 0 (the cube's middle) covers x ∈ [0, 2] m, the image's left half;
// `starsLightSurfaces`: the nebula's stars light it (off: the wall holds the scene's lights alone).
std::string sceneJson(bool wall, const char* method, const char* wallColour = "[0, 0, 0]", const char* lights = "",
                      bool starsLightSurfaces = false) {
  return fmt::format(R"json({{
  "camera": {{"position": [0, 0, -6], "target": [0, 0, 0], "up": [0, 1, 0], "fov_deg": 40, "near": 0.1, "far": 100, "ev100": 0}},
  "materials": {{"black": {{"base_colour_srgb": {}}}}},
  "lights": [{}],
  "objects": [{}],
  "nebula": {{
    "density": {{"noise": {{"resolution": 24, "seed": 7}}}},
    "extinction": 3, "scattering": 1, "emission": 0.002,
    "lines": {{"H I Balmer (case B)": 1.0, "[O III] doublet": 0.8}},
    "stars": [{{"position": [0.5, 0.55, 0.45], "temperature": 12000}}, {{"position": [0.3, 0.4, 0.6], "temperature": 4000, "luminosity": 0.6}}],
    "filters": "cie1931", "box": {{"min": [-2, -2, -2], "size": 4}}, "method": "{}", "intensity": 1,
    "light_surfaces": {}
  }}
}})json",
                     wallColour, lights,
                     wall ? R"({"box": {"centre": [1, 0, 0.5], "size": [2, 6, 1]}, "material": "black"})" : "", method,
                     starsLightSurfaces);
}

struct Frame {
  nebula::NebulaImage gpu, cpu, cpuOpen;  // cpuOpen: without the wall
  const nebula::NebulaPass* pass = nullptr;
  std::vector<double> limits;  // the CPU's, cube units
};

// Renders the scene once and marches the CPU twin from the renderer's camera.
Frame renderBoth(Renderer& renderer, const Scene& scene, bool wall) {
  renderer.renderFrame();
  Frame f;
  f.pass = dynamic_cast<const nebula::NebulaPass*>(renderer.techniquePass(nebula::NebulaSection::kKey));
  EXPECT_NE(f.pass, nullptr);
  std::vector<float> mean = renderer.readMeanTristimulus();
  f.gpu = {kSize, kSize, std::vector<glm::vec3>(mean.size() / 3)};
  for (std::size_t i = 0; i < f.gpu.pixels.size(); ++i) f.gpu.pixels[i] = {mean[3 * i], mean[3 * i + 1], mean[3 * i + 2]};

  const auto& section = *scene.techniques.find<nebula::NebulaSection>();
  nebula::NebulaModel model = section.fullModel();
  model.camera = {{0.5, 0.5, -1.0}, {0.5, 0.5, 0.5}, 40.0, kSize, kSize};
  nebula::RenderSettings s = f.pass->lastSettings();
  if (wall) {  // the face z = 0 m (0.5 in the cube) over x ∈ [0, 2] m: the ray's distance to it
    const double tanHalf = std::tan(20.0 * 3.14159265358979323846 / 180.0);
    for (int row = 0; row < kSize; ++row)
      for (int px = 0; px < kSize; ++px) {
        double u = (2.0 * (px + 0.5) / kSize - 1.0) * tanHalf, v = (1.0 - 2.0 * (row + 0.5) / kSize) * tanHalf;
        glm::dvec3 dir = glm::normalize(glm::dvec3(-u, v, 1.0));  // forward +z, right −x, up +y
        double t = 6.0 / dir.z, x = t * dir.x;
        f.limits.push_back(x > 0.0 && x < 2.0 ? t / 4.0 : 1e30);
      }
    s.rayLimits = f.limits;
  }
  nebula::NebulaRenderer cpu(model, s);
  f.cpu = cpu.render(s);
  s.rayLimits.clear();
  f.cpuOpen = cpu.render(s);
  return f;
}

void expectTwins(const Frame& f, const char* what) {
  ASSERT_GT(nebula::peakOf(f.cpu), 0.0);
  double ratio = nebula::twinRatio(f.gpu, f.cpu, *f.pass->marcher(), f.pass->lastSettings().steps);
  std::printf("%s: the renderer's nebula against the CPU marcher, max relative %.3g, %.3g of the bound\n", what,
              nebula::relativeError(f.gpu, f.cpu), ratio);
  EXPECT_LE(ratio, 1.0);
}

// A scene's nebula lit from behind through thick dust sends its light beyond the projection
// basis (nebula_basis_coverage.h): its precomputation says so in one line naming the scene, and
// says nothing once the section's basis is fitted as deep as it advises (120 steps, each within
// τ = 0.5: the march's steps are not warned of). No GPU: the precomputation is the CPU's.
TEST(NebulaPass, ThePrecomputationWarnsOfLightBeyondTheBasis) {
  auto warning = [](const std::string& basis) {
    const std::string json = fmt::format(R"json({{
  "camera": {{"position": [0, 0, -6], "target": [0, 0, 0], "up": [0, 1, 0], "fov_deg": 40}},
  "materials": {{}}, "lights": [], "objects": [],
  "nebula": {{
    "density": {{"noise": {{"resolution": 16, "seed": 7, "bias": 0.8}}}}, "extinction": 25, "scattering": 1, "emission": 0,
    "stars": [{{"position": [0.5, 0.5, 1.4], "temperature": 12000}}], "filters": "cie1931",
    "box": {{"min": [-2, -2, -2], "size": 4}}, "method": "projection", "steps": 120{}
  }}
}})json", basis);
    const Scene scene = loadScene(writeTempFile("nebula_backlit.json", json));
    ::testing::internal::CaptureStderr();
    nebula::NebulaPass::precompute(scene, {});
    return ::testing::internal::GetCapturedStderr();
  };
  const std::string shallow = warning("");
  EXPECT_NE(shallow.find("nebula_backlit.json: /nebula: up to 100 % of a pixel's star light"), std::string::npos) << shallow;
  EXPECT_NE(shallow.find("\"basis_depth\": "), std::string::npos) << shallow;
  const std::string deep = warning(R"(, "basis": 6, "basis_depth": 16)");
  EXPECT_EQ(deep.find("warning"), std::string::npos) << deep;
}

TEST(NebulaPass, TheFramesNebulaIsTheCpuMarchersFromTheSameCamera) {
  gpu::HeadlessContext context;
  for (const char* method : {"projection", "light-density"}) {
    Scene scene = loadScene(writeTempFile(fmt::format("nebula_{}.json", method), sceneJson(false, method)));
    FrameSettings settings;
    settings.width = settings.height = kSize;
    settings.display.dither = false;
    Renderer renderer(scene, cachedTestTable(), settings);
    Frame f = renderBoth(renderer, scene, false);
    expectTwins(f, method);
    // A still view marches once: later frames add the same image.
    renderer.renderFrame();
    renderer.renderFrame();
    EXPECT_EQ(f.pass->marches(), 1);
    // A passband moved and widened: the pass refilters its volume (NebulaSection::volumeKey) and
    // finishes the same march through the new weights, and the frame is the CPU twin's of the
    // edited model.
    scene.techniques.find<nebula::NebulaSection>()->model.passbands[1] = {25.0, 1.5};
    renderer.sceneChanged();
    Frame edited = renderBoth(renderer, scene, false);
    EXPECT_EQ(edited.pass->marches(), 1);
    expectTwins(edited, fmt::format("{}, ȳ moved 25 nm and × 1.5", method).c_str());
    EXPECT_GT(nebula::relativeError(edited.gpu, f.gpu), 1e-2);
  }
}

TEST(NebulaPass, RaysStopAtTheScenesSurfaces) {
  gpu::HeadlessContext context;
  Scene scene = loadScene(writeTempFile("nebula_wall.json", sceneJson(true, "projection")));
  FrameSettings settings;
  settings.width = settings.height = kSize;
  settings.display.dither = false;
  Renderer renderer(scene, cachedTestTable(), settings);
  Frame f = renderBoth(renderer, scene, true);
  // Pixels whose ray has a sample within 1e-4 of the cube (4e-4 m) of the wall, or which lie
  // within half a pixel of its edge, may take or drop that sample by the depth buffer's rounding:
  // left out, like the CPU's.
  const double tanHalf = std::tan(20.0 * 3.14159265358979323846 / 180.0);
  std::size_t kept = 0;
  double walledGpu = 0.0, walledOpen = 0.0;
  nebula::NebulaImage gpuKept = f.gpu, cpuKept = f.cpu;
  for (int row = 0; row < kSize; ++row)
    for (int px = 0; px < kSize; ++px) {
      const std::size_t i = static_cast<std::size_t>(row * kSize + px);
      const double edge = std::abs(px + 0.5 - kSize / 2.0);
      bool ambiguous = edge < 1.0;
      if (f.limits[i] < 1e29) {
        double u = (2.0 * (px + 0.5) / kSize - 1.0) * tanHalf, v = (1.0 - 2.0 * (row + 0.5) / kSize) * tanHalf;
        glm::dvec3 dir = glm::normalize(glm::dvec3(-u, v, 1.0));
        // The cube's faces along the ray (the CPU's clipToCube): z from 0 to 1 in the cube.
        double t0 = (0.0 - -1.0) / dir.z, t1 = (1.0 - -1.0) / dir.z;
        for (int a = 0; a < 2; ++a) {
          double p = 0.5, d = a == 0 ? dir.x : dir.y;
          if (std::abs(d) > 1e-15) t1 = std::min(t1, std::max((0.0 - p) / d, (1.0 - p) / d));
        }
        for (int k = 0; k < 100; ++k)
          ambiguous = ambiguous || std::abs(t0 + (k + 0.5) * (t1 - t0) / 100.0 - f.limits[i]) < 1e-4;
        walledGpu += f.gpu.pixels[i].y;
        walledOpen += f.cpuOpen.pixels[i].y;
      }
      if (ambiguous) {
        gpuKept.pixels[i] = cpuKept.pixels[i] = glm::vec3(0.0f);
      } else {
        ++kept;
      }
    }
  std::printf("wall: %zu of %d pixels compared\n", kept, kSize * kSize);
  EXPECT_GT(kept, static_cast<std::size_t>(kSize * kSize * 9 / 10));
  expectTwins({gpuKept, cpuKept, {}, f.pass, f.limits}, "wall");
  // What the wall hides is not nothing: the far half's light.
  std::printf("Y over the wall's pixels: %.4g, %.4g without the wall\n", walledGpu, walledOpen);
  EXPECT_LT(walledGpu, 0.9 * walledOpen);
}

// One 40 × 40 frame of a nebula scene in `mode` against the CPU twin: at every pixel the
// accumulation against the twin's lighting of its G-buffer texel (with the nebula pass's texels
// read back: its optical depth and star depths) plus the nebula's channels. At the pixels of an
// object `onObject(lit, open)` sees that lighting and the twin's without the nebula's texels
// (nothing dimmed, no star light); returns the largest relative difference.
template <class OnObject>
double compareWithTheTwin(const Scene& scene, RenderMode mode, OnObject onObject) {
  FrameSettings settings;
  settings.width = settings.height = kSize;
  settings.mode = mode;
  settings.shadowMapSize = 256;
  settings.lookup = UpsamplingLookup::Manual;  // the CPU's lookup, bit for bit
  settings.display.dither = false;
  Renderer renderer(scene, cachedTestTable(), settings);
  renderer.renderFrame();
  const TechniquePass* technique = renderer.techniquePass(nebula::NebulaSection::kKey);
  const auto* pass = dynamic_cast<const nebula::NebulaPass*>(technique);
  EXPECT_NE(pass, nullptr);
  if (!pass) return 1e30;
  const std::vector<glm::vec4> nebulaColour = pass->marcher()->colour().read<glm::vec4>();  // row 0 at the top
  GBufferReadback g(renderer);
  CpuShading cpu(renderer.frameData(), cachedTestTable(), g.shadowLayers,
                 {{std::string(nebula::NebulaSection::kKey), technique->readTexels()}});
  CpuShading undimmed(renderer.frameData(), cachedTestTable(), g.shadowLayers);
  double worst = 0.0;
  for (int y = 0; y < kSize; ++y)
    for (int x = 0; x < kSize; ++x) {
      const std::size_t i = static_cast<std::size_t>(y * kSize + x);
      const glm::vec2 uv((static_cast<float>(x) + 0.5f) / kSize, (static_cast<float>(y) + 0.5f) / kSize);
      const GBufferTexel t = g.texel(i);
      const glm::dvec3 lit(cpu.shade(t, uv, renderer.cameraTransform()));
      const glm::dvec3 expected = lit + glm::dvec3(nebulaColour[static_cast<std::size_t>((kSize - 1 - y) * kSize + x)]);
      const glm::dvec3 actual(g.accumulated(i));
      const double scale = std::max({std::abs(expected.x), std::abs(expected.y), std::abs(expected.z), 1e-3});
      worst = worstOf(worst, glm::length(actual - expected) / scale);
      if (t.materialId != 0) onObject(lit, glm::dvec3(undimmed.shade(t, uv, renderer.cameraTransform())));
    }
  return worst;
}

// What lies behind the nebula is dimmed per wavelength by e^(−g/λ) in the lighting pass, g the
// optical depth the march left in front of each pixel: a lit white wall through the middle of the
// cube, in 16-wavelength frames and in RGB (at R, G and B's stand-in wavelengths), is the CPU
// twin's lighting of its G-buffer texel with the pass's optical depth read back (shared
// pixel_shading.glsl) plus the nebula's channels, at every pixel, the background's included; and
// the nebula in front dims and reddens it.
TEST(NebulaPass, WhatLiesBehindIsDimmedPerWavelength) {
  gpu::HeadlessContext context;
  Scene scene = loadScene(writeTempFile(
      "nebula_lit_wall.json",
      sceneJson(true, "projection", "[0.8, 0.8, 0.8]",
                R"({"type": "directional", "direction": [0.2, -0.3, 1], "spd": "D65", "intensity": 3})")));
  for (RenderMode mode : {RenderMode::JakobHanika, RenderMode::Rgb}) {
    double dimming = 0.0, zOverY = 0.0, zOverYUndimmed = 0.0;
    int wall = 0;
    const double worst = compareWithTheTwin(scene, mode, [&](const glm::dvec3& lit, const glm::dvec3& open) {
      dimming += lit.y / open.y;
      zOverY += lit.z / lit.y;
      zOverYUndimmed += open.z / open.y;
      ++wall;
    });
    dimming /= wall;
    std::printf("the lit wall behind the nebula, %s: %d pixels; GPU against the CPU twin, relative error max %.3g; "
                "Y dimmed to %.3f on average, Z/Y %.3f → %.3f\n",
                std::string(renderModeName(mode)).c_str(), wall, worst, dimming, zOverYUndimmed / wall, zOverY / wall);
    EXPECT_GT(wall, kSize * kSize / 3);
    EXPECT_LE(worst, 1e-4);
    EXPECT_LT(dimming, 0.95);
    EXPECT_LT(zOverY, 0.97 * zOverYUndimmed);  // blue is dimmed most: e^(−g/λ)
  }
}

// The nebula's stars light the scene's surfaces (shared/nebula_lighting.glsl): the white wall
// through the cube with no other light, in 16-wavelength frames and in RGB, is at every pixel the
// CPU twin's lighting of its G-buffer texel — each star's intensity from the section's block, its
// dimming from the star depths the pass marched with — plus the nebula's channels; the stars are
// all that lights it (the twin without the pass's texels has no star light). With 18 stars, more
// than the lighting pass keeps lookups for (kMaxLights), as well.
TEST(NebulaPass, ItsStarsLightTheScenesSurfaces) {
  gpu::HeadlessContext context;
  Scene twoStars = loadScene(writeTempFile("nebula_star_lit_wall.json", sceneJson(true, "projection", "[0.8, 0.8, 0.8]", "", true)));
  Scene manyStars = twoStars;
  auto& stars = manyStars.techniques.find<nebula::NebulaSection>()->model.stars;
  for (int k = 0; k < 16; ++k) stars.push_back({{0.1 + 0.05 * k, 0.2 + 0.04 * k, 0.05 + 0.02 * k}, 3000.0 + 1000.0 * k, 0.3});
  for (auto [scene, mode] : {std::pair{&twoStars, RenderMode::JakobHanika}, std::pair{&twoStars, RenderMode::Rgb},
                             std::pair{&manyStars, RenderMode::JakobHanika}}) {
    double wallY = 0.0, withoutStars = 0.0;
    int wall = 0;
    const double worst = compareWithTheTwin(*scene, mode, [&](const glm::dvec3& lit, const glm::dvec3& open) {
      wallY += lit.y;
      withoutStars += open.y;
      ++wall;
    });
    std::printf("the wall lit by the nebula's %zu stars alone, %s: %d pixels, mean Y %.4g; GPU against the CPU "
                "twin, relative error max %.3g\n",
                scene->techniques.find<nebula::NebulaSection>()->model.stars.size(),
                std::string(renderModeName(mode)).c_str(), wall, wallY / wall, worst);
    EXPECT_GT(wall, kSize * kSize / 3);
    EXPECT_GT(wallY / wall, 1e-4);
    EXPECT_EQ(withoutStars, 0.0);
    EXPECT_LE(worst, 1e-4);
  }
}

}  // namespace
}  // namespace prism::render
