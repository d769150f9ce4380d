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

#include <unistd.h>

#include "gpu/headless_context.h"
#include "gpu/texture.h"
#include "render/cpu_shading.h"
#include "render/gbuffer_readback_test_support.h"
#include "scene/scene_loader.h"
#include "spectral/illuminant.h"
#include "spectral/table_test_support.h"
#include "techniques/prt/gpu/prt_pass.h"
#include "techniques/prt/prt_section.h"

namespace prism::render {
namespace {

const std::filesystem::path kExampleScenes = PRISM_SCENES_DIR;

struct Hit {
  std::size_t triangle = 0;
  glm::dvec3 barycentric{0.0};
  double distance = 0.0;
};

// The nearest triangle along the ray (Möller & Trumbore 1997), in double.
std::optional<Hit> intersect(const prt::PrtDrawData& d, const glm::dvec3& origin, const glm::dvec3& dir) {
  std::optional<Hit> best;
  for (std::size_t t = 0; t + 2 < d.indices.size(); t += 3) {
    glm::dvec3 a(d.positionsW[d.indices[t]]), b(d.positionsW[d.indices[t + 1]]), c(d.positionsW[d.indices[t + 2]]);
    glm::dvec3 e1 = b - a, e2 = c - a, p = glm::cross(dir, e2);
    double det = glm::dot(e1, p);
    if (std::abs(det) < 1e-14) continue;
    glm::dvec3 s = origin - a;
    double u = glm::dot(s, p) / det;
    if (u < 0.0 || u > 1.0) continue;
    glm::dvec3 q = glm::cross(s, e1);
    double v = glm::dot(dir, q) / det;
    if (v < 0.0 || u + v > 1.0) continue;
    double distance = glm::dot(e2, q) / det;
    if (distance <= 0.0 || (best && distance >= best->distance)) continue;
    best = Hit{t, glm::dvec3(1.0 - u - v, u, v), distance};
  }
  return best;
}

// The ray through window position (x, y) (GL's: y up, pixel centres at +0.5).
std::pair<glm::dvec3, glm::dvec3> pixelRay(const CameraTransform& camera, double x, double y, int w, int h) {
  glm::dvec2 ndc(2.0 * x / w - 1.0, 2.0 * y / h - 1.0);
  glm::dmat4 inverse(camera.inverseViewProjection);
  glm::dvec4 nearPoint = inverse * glm::dvec4(ndc, -1.0, 1.0), farPoint = inverse * glm::dvec4(ndc, 1.0, 1.0);
  glm::dvec3 n = glm::dvec3(nearPoint) / nearPoint.w, f = glm::dvec3(farPoint) / farPoint.w;
  return {n, glm::normalize(f - n)};
}

// The hit through pixel (x, y)'s centre when the pixel lies inside one object (rays half a pixel
// away hit the same material): a silhouette's pixels may take another triangle's colour.
std::optional<Hit> interiorHit(const prt::PrtDrawData& d, const CameraTransform& camera, int x, int y, int w, int h) {
  auto [origin, dir] = pixelRay(camera, x + 0.5, y + 0.5, w, h);
  std::optional<Hit> hit = intersect(d, origin, dir);
  if (!hit) return std::nullopt;
  for (glm::dvec2 o : {glm::dvec2(-0.5, 0.0), glm::dvec2(0.5, 0.0), glm::dvec2(0.0, -0.5), glm::dvec2(0.0, 0.5)}) {
    auto [o2, d2] = pixelRay(camera, x + 0.5 + o.x, y + 0.5 + o.y, w, h);
    std::optional<Hit> h2 = intersect(d, o2, d2);
    if (!h2 || d.vertexMaterial[d.indices[h2->triangle]] != d.vertexMaterial[d.indices[hit->triangle]]) return std::nullopt;
  }
  return hit;
}

// The fragment shader's sum on the CPU: Ê interpolated with the hit's barycentrics, then prtXyz,
// for every projection (the 5 nm reference has six).
glm::dvec3 cpuTristimulus(const prt::PrtDrawData& d, const Hit& hit) {
  glm::dvec3 sum(0.0);
  const int material = d.vertexMaterial[d.indices[hit.triangle]];
  for (const prt::PrtProjection& p : d.projections) {
    shared::PrtBasisIrradiance e{};
    for (int k = 0; k < 3; ++k) {
      std::uint32_t v = d.indices[hit.triangle + static_cast<std::size_t>(k)];
      shared::PrtBasisIrradiance ev = shared::prtVertexIrradiance(p.environment, d.transfer[v], p.basisCount);
      for (int j = 0; j < p.basisCount; ++j) e.e[j] += static_cast<float>(hit.barycentric[k]) * ev.e[j];
    }
    sum += glm::dvec3(shared::prtXyz(e, p.reflectances[static_cast<std::size_t>(material)], p.basisCount));
  }
  return sum;
}

struct PrtParityCase {
  prt::PrtMode mode;
  RenderMode frameMode;
};

class PrtGpuCpuParity : public testing::TestWithParam<PrtParityCase> {};

TEST_P(PrtGpuCpuParity, RandomPixelsAgreeWithTheSharedSums) {
  gpu::HeadlessContext context;
  Scene scene = loadScene(kExampleScenes / "prt_metamers.json");
  scene.techniques.find<prt::PrtSection>()->mode = GetParam().mode;
  FrameSettings settings;
  settings.width = 160;
  settings.height = 90;
  settings.mode = GetParam().frameMode;
  settings.shadowMapSize = 256;
  settings.display.dither = false;
  Renderer renderer(scene, cachedTestTable(), settings);
  renderer.renderFrame();
  const TechniquePass* pass = renderer.techniquePass(prt::PrtSection::kKey);
  ASSERT_TRUE(pass);
  auto data = std::dynamic_pointer_cast<const prt::PrtDrawData>(pass->readTexels());
  ASSERT_TRUE(data);
  ASSERT_FALSE(data->projections.empty());
  std::vector<float> lit = gpu::readTexture2DFloat(renderer.accumulation(), 4);

  const int w = settings.width, h = settings.height;
  std::mt19937 rng(14);
  std::uniform_int_distribution<int> px(0, w - 1), py(0, h - 1);
  double worst = 0.0, sum = 0.0;
  int compared = 0;
  for (int n = 0; n < 400; ++n) {
    int x = px(rng), y = py(rng);  // GL rows
    std::optional<Hit> hit = interiorHit(*data, renderer.cameraTransform(), x, y, w, h);
    if (!hit) continue;
    glm::dvec3 expected = cpuTristimulus(*data, *hit);
    std::size_t i = static_cast<std::size_t>(y * w + x);
    glm::dvec3 actual(lit[4 * i], lit[4 * i + 1], lit[4 * i + 2]);
    double scale = std::max({std::abs(expected.x), std::abs(expected.y), std::abs(expected.z)});
    double error = glm::length(actual - expected) / scale;
    worst = std::max(worst, error);
    sum += error;
    ++compared;
  }
  std::printf("PRT %s (frame %s): %d pixels compared; relative error mean %.3g, max %.3g\n",
              std::string(prt::prtModeName(GetParam().mode)).c_str(),
              std::string(renderModeName(GetParam().frameMode)).c_str(), compared, sum / std::max(compared, 1), worst);
  EXPECT_GT(compared, 100);
  EXPECT_LE(worst, 1e-4);
}

INSTANTIATE_TEST_SUITE_P(Modes, PrtGpuCpuParity,
                         testing::Values(PrtParityCase{prt::PrtMode::Spectral, RenderMode::JakobHanika},
                                         PrtParityCase{prt::PrtMode::Reference5nm, RenderMode::JakobHanika},
                                         PrtParityCase{prt::PrtMode::Spectral, RenderMode::Rgb}),
                         [](const testing::TestParamInfo<PrtParityCase>& param) {
                           std::string name = std::string(prt::prtModeName(param.param.mode)) + "_frame_" +
                                              std::string(renderModeName(param.param.frameMode));
                           std::replace(name.begin(), name.end(), '-', '_');
                           return name;
                         });

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
  FrameSettings settings;
  settings.width = 160;
  settings.height = 90;
  settings.shadowMapSize = 256;
  settings.display.dither = false;
  Renderer renderer(scene, cachedTestTable(), settings);
  renderer.renderFrame();
  auto data = std::dynamic_pointer_cast<const prt::PrtDrawData>(renderer.techniquePass(prt::PrtSection::kKey)->readTexels());
  ASSERT_TRUE(data);
  const int w = settings.width, h = settings.height;
  GBufferReadback g(renderer);
  CpuShading cpu(renderer.frameData(), cachedTestTable(), g.shadowLayers);

  std::mt19937 rng(15);
  std::uniform_int_distribution<int> px(0, w - 1), py(0, h - 1);
  double worst = 0.0, lightShare = 0.0;
  int compared = 0;
  for (int n = 0; n < 400; ++n) {
    int x = px(rng), y = py(rng);
    std::optional<Hit> hit = interiorHit(*data, renderer.cameraTransform(), x, y, w, h);
    if (!hit) continue;
    std::size_t i = static_cast<std::size_t>(y * w + x);
    GBufferTexel t = g.texel(i);
    ASSERT_NE(t.materialId & shared::kTechniqueShadedBit, 0u);
    glm::vec2 uv((static_cast<float>(x) + 0.5f) / static_cast<float>(w), (static_cast<float>(y) + 0.5f) / static_cast<float>(h));
    const glm::dvec3 lights(cpu.shade(t, uv, renderer.cameraTransform()));
    const glm::dvec3 expected = lights + cpuTristimulus(*data, *hit);
    const glm::dvec3 actual(g.accumulated(i));
    const double scale = std::max({std::abs(expected.x), std::abs(expected.y), std::abs(expected.z)});
    worst = std::max(worst, glm::length(actual - expected) / scale);
    lightShare += lights.y / expected.y;
    ++compared;
  }
  lightShare /= std::max(compared, 1);
  std::printf("PRT objects under a light: %d pixels compared; relative error max %.3g; the light's mean share of Y %.2f\n",
              compared, worst, lightShare);
  EXPECT_GT(compared, 100);
  EXPECT_LE(worst, 1e-4);
  EXPECT_GT(lightShare, 0.3);
}

// The bake ahead of the renderer (precomputeTechniques) fills the cache entry the pass then reads:
// progress once, named, up to its total; nothing the second time, nor for a scene without PRT.
TEST(PrtPrecompute, BakesAheadIntoTheCacheThePassReads) {
  const std::filesystem::path cache =
      std::filesystem::path(::testing::TempDir()) / ("prism_prt_precompute_" + std::to_string(::getpid()));
  std::filesystem::remove_all(cache);
  const char* previous = std::getenv("PRISM_CACHE_DIR");
  const std::string restore = previous ? previous : "";
  ::setenv("PRISM_CACHE_DIR", cache.c_str(), 1);
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
  if (previous) ::setenv("PRISM_CACHE_DIR", restore.c_str(), 1);
  else ::unsetenv("PRISM_CACHE_DIR");
  std::filesystem::remove_all(cache);
}

}  // namespace
}  // namespace prism::render
