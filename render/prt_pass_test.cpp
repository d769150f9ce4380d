// The PRT forward pass on the GPU (llvmpipe in CI) against its CPU twin: at random pixels of a
// PRT scene, the accumulated tristimulus against shaders/shared/prt.glsl compiled as C++ over the
// very data the pass uploaded (PrtPass::readTexels: transfer, L̃, R̂). The CPU finds the pixel's
// triangle by a ray through the pixel's centre and interpolates the vertices' Ê with the hit's
// barycentrics (perspective-correct interpolation is interpolation on the triangle in space),
// then sums prtXyz as the fragment shader does.
#include "render/renderer.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <optional>
#include <random>
#include <string>
#include <vector>

#include "core/cache_dir_test_support.h"
#include "core/worst_of.h"
#include "gpu/headless_context.h"
#include "gpu/texture.h"
#include "render/cpu_shading.h"
#include "render/gbuffer_readback_test_support.h"
#include "render/prt_twin_test_support.h"
#include "scene/scene_loader.h"
#include "spectral/illuminant.h"
#include "spectral/table_test_support.h"
#include "techniques/prt/gpu/prt_pass.h"
#include "techniques/nebula/nebula_cpu_twin.h"
#include "techniques/nebula/nebula_section.h"
#include "techniques/prt/prt_section.h"

namespace prism::render {
namespace {

const std::filesystem::path kExampleScenes = PRISM_SCENES_DIR;

// `prt_metamers` (with `sets` applied) in the case's mode: at 400 random pixels' interior ones, the
// accumulated tristimulus against the twins (the lighting pass's, then the PRT sums), within the
// renderer's 1e-4. Under water, the water must also take a visible share of the light (what the
// twin keeps of its dry sum, on average) and add its in-scattering of the environment.
void expectRandomPixelsAgreeWithTheSharedSums(const PrtModeCase& mode, const std::vector<std::string>& sets,
                                              unsigned seed) {
  gpu::HeadlessContext context;
  Scene scene = loadScene(kExampleScenes / "prt_metamers.json", sets);
  scene.techniques.find<prt::PrtSection>()->mode = mode.mode;
  const FrameSettings settings = prtTwinSettings(mode, 160, 90);
  Renderer renderer(scene, cachedTestTable(), settings);
  renderer.renderFrame();
  const TechniquePass* pass = renderer.techniquePass(prt::PrtSection::kKey);
  ASSERT_TRUE(pass);
  auto data = std::dynamic_pointer_cast<const prt::PrtDrawData>(pass->readTexels());
  ASSERT_TRUE(data);
  ASSERT_FALSE(data->projections.empty());
  ASSERT_EQ(data->medium.has_value(), !sets.empty());
  prt::PrtDrawData dry = *data;
  dry.medium.reset();
  std::vector<float> lit = gpu::readTexture2DFloat(renderer.accumulation(), 4);
  LightingTwin lighting(renderer, cachedTestTable());

  const int w = settings.width, h = settings.height;
  const glm::vec3 camera = renderer.cameraTransform().position;
  double worst = 0.0, sum = 0.0, kept = 0.0, haze = 0.0;
  const int compared = forRandomInteriorPixels(*data, renderer.cameraTransform(), w, h, seed, 400, [&](int x, int y, const Hit& hit) {
    const glm::dvec3 prtSums = cpuTristimulus(*data, hit, camera), lit0 = lighting.at(x, y);
    const glm::dvec3 expected = prtSums + lit0;
    const std::size_t i = static_cast<std::size_t>(y * w + x);
    const glm::dvec3 actual(lit[4 * i], lit[4 * i + 1], lit[4 * i + 2]);
    const double scale = std::max({std::abs(expected.x), std::abs(expected.y), std::abs(expected.z)});
    const double error = glm::length(actual - expected) / scale;
    worst = worstOf(worst, error);
    sum += error;
    kept += prtSums.y / cpuTristimulus(dry, hit, camera).y;
    haze += lit0.y / expected.y;
  });
  kept /= std::max(compared, 1);
  haze /= std::max(compared, 1);
  std::printf("PRT %s (frame %s)%s: %d pixels compared; relative error mean %.3g, max %.3g; the medium keeps %.3f "
              "of Y, the lighting pass adds %.3f of it\n",
              std::string(prt::prtModeName(mode.mode)).c_str(), std::string(renderModeName(mode.frameMode)).c_str(),
              sets.empty() ? "" : " under water", compared, sum / std::max(compared, 1), worst, kept, haze);
  EXPECT_GT(compared, 100);
  EXPECT_LE(worst, 1e-4);
  if (sets.empty()) {
    EXPECT_EQ(haze, 0.0);  // no light but the environment, which PRT's sums carry
  } else {
    EXPECT_LT(kept, 0.8);
    EXPECT_GT(haze, 0.05);  // the water's in-scattering of the environment
  }
}

class PrtGpuCpuParity : public testing::TestWithParam<PrtModeCase> {};

TEST_P(PrtGpuCpuParity, RandomPixelsAgreeWithTheSharedSums) { expectRandomPixelsAgreeWithTheSharedSums(GetParam(), {}, 14); }

// Under water (a Jerlov II ocean whose surface lies 2 m above the camera, the objects 3–4 m
// down): the fragment shader's sum over the projection's nodes, dimmed by the water between the
// camera and the fragment and above the fragment (shared/prt_medium.glsl), against the same sum
// on the CPU.
TEST_P(PrtGpuCpuParity, RandomPixelsAgreeWithTheSharedSumsThroughTheWater) {
  expectRandomPixelsAgreeWithTheSharedSums(GetParam(), {R"(water={"type": "II", "depth": 2})"}, 16);
}

INSTANTIATE_TEST_SUITE_P(Modes, PrtGpuCpuParity, prtModeCases(), prtModeCaseName);

// Inside a nebula (scenes/nebula_field.json, its moon a PRT object under a uniform D65
// environment; the scene's light, the nebula's emission, scattering and star light taken out so that the
// moon's pixels hold PRT's sums alone): the fragment shader dims each node by e^(−g/λ), g the
// nebula's optical depth at the pixel, which the renderer binds for the forward pass as for
// lighting; the CPU twin reads the same g back (NebulaPass::readTexels).
TEST(PrtGpuCpuParity, PrtObjectsInsideANebulaAreDimmedByIt) {
  gpu::HeadlessContext context;
  Scene scene = loadScene(kExampleScenes / "nebula_field.json",
                          {R"(prt={"environment": {"illuminant": "D65", "shape": "uniform", "luminance": 2}})",
                           "objects.1.technique=prt", "nebula.emission=0", "nebula.scattering=0",
                           "nebula.light_surfaces=false"});
  scene.lights.clear();
  const FrameSettings settings = prtTwinSettings({prt::PrtMode::Spectral, RenderMode::JakobHanika}, 160, 90);
  Renderer renderer(scene, cachedTestTable(), settings);
  renderer.renderFrame();
  auto data = std::dynamic_pointer_cast<const prt::PrtDrawData>(renderer.techniquePass(prt::PrtSection::kKey)->readTexels());
  auto nebula = std::dynamic_pointer_cast<const nebula::NebulaTexels>(
      renderer.techniquePass(nebula::NebulaSection::kKey)->readTexels());
  ASSERT_TRUE(data);
  ASSERT_TRUE(nebula);
  ASSERT_FALSE(data->medium);
  const int w = settings.width, h = settings.height;
  ASSERT_EQ(nebula->width, w);
  ASSERT_EQ(nebula->height, h);
  std::vector<float> lit = gpu::readTexture2DFloat(renderer.accumulation(), 4);
  double worst = 0.0, kept = 1.0, depth = 0.0;
  const int compared = forInteriorPixels(*data, renderer.cameraTransform(), w, h, [&](int x, int y, const Hit& hit) {
    const std::size_t i = static_cast<std::size_t>(y * w + x);
    const float g = nebula->opticalDepthUm[i];
    const glm::dvec3 expected = cpuTristimulus(*data, hit, renderer.cameraTransform().position, g);
    const glm::dvec3 actual(lit[4 * i], lit[4 * i + 1], lit[4 * i + 2]);
    const double scale = std::max({std::abs(expected.x), std::abs(expected.y), std::abs(expected.z)});
    worst = worstOf(worst, glm::length(actual - expected) / scale);
    kept = std::min(kept, expected.y / cpuTristimulus(*data, hit, renderer.cameraTransform().position).y);
    depth = std::max(depth, static_cast<double>(g));
  });
  std::printf("PRT moon inside the nebula: %d pixels compared; relative error max %.3g; optical depth up to %.3f µm, "
              "keeping down to %.3f of Y\n",
              compared, worst, depth, kept);
  EXPECT_GT(compared, 100);
  EXPECT_LE(worst, 1e-4);
  EXPECT_LT(kept, 0.9);
}

// PRT objects are lit by the scene's lights too, in the lighting pass, as Lambertian surfaces with
// shadow maps (the sun of PRT's spectral sky is such a light): at interior pixels of the metamer
// scene under a D65 light 40° from the zenith, the accumulation is the CPU twin's lighting of the
// G-buffer texel (shared pixel_shading.glsl, the shadow maps read back) plus the PRT sums, and the
// light adds a visible share.
TEST(PrtGpuCpuParity, PrtObjectsAreLitByTheScenesLightsToo) {
  gpu::HeadlessContext context;
  Scene scene = loadScene(kExampleScenes / "prt_metamers.json");
  Light sun;
  sun.direction = glm::normalize(glm::vec3(0.4f, -0.766f, -0.3f));
  sun.spd = normalisedLightSpectrum(illuminant("D65"));
  sun.intensity = 3000.0f;
  scene.lights.push_back(sun);
  const FrameSettings settings = prtTwinSettings({prt::PrtMode::Spectral, RenderMode::JakobHanika}, 160, 90);
  Renderer renderer(scene, cachedTestTable(), settings);
  renderer.renderFrame();
  auto data = std::dynamic_pointer_cast<const prt::PrtDrawData>(renderer.techniquePass(prt::PrtSection::kKey)->readTexels());
  ASSERT_TRUE(data);
  const int w = settings.width, h = settings.height;
  GBufferReadback g(renderer);
  CpuShading cpu(renderer.frameData(), cachedTestTable(), g.shadowLayers);

  double worst = 0.0, lightShare = 0.0;
  const int compared = forRandomInteriorPixels(*data, renderer.cameraTransform(), w, h, 15, 400, [&](int x, int y, const Hit& hit) {
    std::size_t i = static_cast<std::size_t>(y * w + x);
    GBufferTexel t = g.texel(i);
    EXPECT_NE(t.materialId & shared::kTechniqueShadedBit, 0u);
    glm::vec2 uv((static_cast<float>(x) + 0.5f) / static_cast<float>(w), (static_cast<float>(y) + 0.5f) / static_cast<float>(h));
    const glm::dvec3 lights(cpu.shade(t, uv, renderer.cameraTransform()));
    const glm::dvec3 expected = lights + cpuTristimulus(*data, hit, renderer.cameraTransform().position);
    const glm::dvec3 actual(g.accumulated(i));
    const double scale = std::max({std::abs(expected.x), std::abs(expected.y), std::abs(expected.z)});
    worst = worstOf(worst, glm::length(actual - expected) / scale);
    lightShare += lights.y / expected.y;
  });
  lightShare /= std::max(compared, 1);
  std::printf("PRT objects under a light: %d pixels compared; relative error max %.3g; the light's mean share of Y %.2f\n",
              compared, worst, lightShare);
  EXPECT_GT(compared, 100);
  EXPECT_LE(worst, 1e-4);
  EXPECT_GT(lightShare, 0.3);
}

// Inside a nebula whose stars light surfaces (the moon of the test above, the star light on): the
// lighting pass lights the PRT object with the stars as it does any surface, so the accumulation is
// the CPU twin's lighting of the G-buffer texel (the star depths the nebula's pass marched with)
// plus the PRT sums dimmed by the nebula in front, and the stars add a visible share.
TEST(PrtGpuCpuParity, PrtObjectsInsideANebulaAreLitByItsStars) {
  gpu::HeadlessContext context;
  Scene scene = loadScene(kExampleScenes / "nebula_field.json",
                          {R"(prt={"environment": {"illuminant": "D65", "shape": "uniform", "luminance": 2}})",
                           "objects.1.technique=prt", "nebula.emission=0", "nebula.scattering=0"});
  scene.lights.clear();
  FrameSettings settings = prtTwinSettings({prt::PrtMode::Spectral, RenderMode::JakobHanika}, 160, 90);
  settings.lookup = UpsamplingLookup::Manual;  // the CPU's lookup, bit for bit, for the moon's 1 % albedo
  Renderer renderer(scene, cachedTestTable(), settings);
  renderer.renderFrame();
  auto data = std::dynamic_pointer_cast<const prt::PrtDrawData>(renderer.techniquePass(prt::PrtSection::kKey)->readTexels());
  const std::shared_ptr<const TechniqueTexels> texels = renderer.techniquePass(nebula::NebulaSection::kKey)->readTexels();
  auto nebula = std::dynamic_pointer_cast<const nebula::NebulaTexels>(texels);
  ASSERT_TRUE(data);
  ASSERT_TRUE(nebula);
  const int w = settings.width, h = settings.height;
  GBufferReadback g(renderer);
  CpuShading cpu(renderer.frameData(), cachedTestTable(), g.shadowLayers, {{std::string(nebula::NebulaSection::kKey), texels}});
  double worst = 0.0, starShare = 0.0;
  const int compared = forInteriorPixels(*data, renderer.cameraTransform(), w, h, [&](int x, int y, const Hit& hit) {
    const std::size_t i = static_cast<std::size_t>(y * w + x);
    const glm::vec2 uv((static_cast<float>(x) + 0.5f) / static_cast<float>(w), (static_cast<float>(y) + 0.5f) / static_cast<float>(h));
    const glm::dvec3 stars(cpu.shade(g.texel(i), uv, renderer.cameraTransform()));
    const glm::dvec3 expected =
        stars + cpuTristimulus(*data, hit, renderer.cameraTransform().position, nebula->opticalDepthUm[i]);
    const glm::dvec3 actual(g.accumulated(i));
    const double scale = std::max({std::abs(expected.x), std::abs(expected.y), std::abs(expected.z)});
    worst = worstOf(worst, glm::length(actual - expected) / scale);
    starShare += stars.y / expected.y;
  });
  starShare /= std::max(compared, 1);
  std::printf("PRT moon lit by the nebula's stars: %d pixels compared; relative error max %.3g; the stars' mean share "
              "of Y %.3f\n",
              compared, worst, starShare);
  EXPECT_GT(compared, 100);
  EXPECT_LE(worst, 1e-4);
  EXPECT_GT(starShare, 0.3);
}

// The bake ahead of the renderer (precomputeTechniques) fills the cache entry the pass then reads:
// progress once, named, up to its total; nothing the second time, nor for a scene without PRT.
TEST(PrtPrecompute, BakesAheadIntoTheCacheThePassReads) {
  const ScopedCacheDirectory scoped("prism_prt_precompute");
  const std::filesystem::path& cache = scoped.path();
  Scene scene = loadScene(kExampleScenes / "prt_metamers.json");
  std::vector<std::string> names;
  std::size_t lastDone = 0, lastTotal = 0;
  auto progress = [&](std::string_view what, std::size_t done, std::size_t total) {
    if (names.empty() || names.back() != what) names.emplace_back(what);
    lastDone = done;
    lastTotal = total;
  };
  precomputeTechniques(scene, progress);
  EXPECT_EQ(names, std::vector<std::string>{"PRT transfer bake"});
  EXPECT_GT(lastTotal, 0u);
  EXPECT_EQ(lastDone, lastTotal);
  EXPECT_EQ(std::distance(std::filesystem::directory_iterator(cache / "prt"), {}), 1);

  names.clear();
  precomputeTechniques(scene, progress);  // cached: no work
  precomputeTechniques(loadScene(kExampleScenes / "spheres_d65.json"), progress);
  EXPECT_TRUE(names.empty());

  gpu::HeadlessContext context;  // the pass finds the entry: no second file, the same bytes drawn
  FrameSettings settings;
  settings.width = 32;
  settings.height = 18;
  Renderer renderer(scene, cachedTestTable(), settings);
  renderer.renderFrame();
  EXPECT_EQ(std::distance(std::filesystem::directory_iterator(cache / "prt"), {}), 1);
}

}  // namespace
}  // namespace prism::render
