// Textured PRT objects on the GPU (llvmpipe in CI) against the CPU twin (prt_twin_test_support.h):
// scenes/prt_textures.json — a spectral texture in the samples form, the same chart in the
// coefficients form and an RGB texture upsampled per texel — seen from close, so that the textures
// are magnified (GL_LINEAR on the base level, which the twin filters; pixels whose texel
// footprint would reach the mipmaps are left out, and so are those whose filter mixes different
// texels: uniformTexels), in spectral PRT, the 5 nm reference and an RGB
// frame (RGB-PRT). A textured material's own slot in the projections is black, so a draw that
// missed its texture would be far off.
#include "render/renderer.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <random>
#include <set>
#include <string>

#include "core/error.h"
#include "core/worst_of.h"
#include "gpu/headless_context.h"
#include "gpu/texture.h"
#include "render/gbuffer_readback_test_support.h"
#include "render/prt_twin_test_support.h"
#include "scene/scene_loader.h"
#include "spectral/table_test_support.h"
#include "techniques/prt/gpu/prt_pass.h"
#include "techniques/prt/prt_section.h"

namespace prism::render {
namespace {

class PrtTexturedParity : public testing::TestWithParam<PrtModeCase> {};

// The larger side, in texels, of the texture's step from pixel (x, y) to its right and upper
// neighbours (GL's ρ); infinite when a neighbour leaves the material.
double texelFootprint(const prt::PrtDrawData& d, const CameraTransform& camera, const Hit& hit, int x, int y, int w, int h) {
  const int material = d.vertexMaterial[d.indices[hit.triangle]];
  const prt::PrtTextureSource& texture = *d.textures[static_cast<std::size_t>(material)];
  const glm::dvec2 uv = hitUv(d, hit), size(texture.width(), texture.height());
  double rho = 0.0;
  for (glm::ivec2 step : {glm::ivec2(1, 0), glm::ivec2(0, 1)}) {
    auto [origin, dir] = pixelRay(camera, x + step.x + 0.5, y + step.y + 0.5, w, h);
    std::optional<Hit> next = intersect(d, origin, dir);
    if (!next || d.vertexMaterial[d.indices[next->triangle]] != material) return INFINITY;
    rho = std::max(rho, glm::length((hitUv(d, *next) - uv) * size));
  }
  return rho;
}

// Whether the four texels GL_LINEAR mixes at the hit hold the same R̂ (in every projection): where
// they do, the value does not hang on the filter's weights, which llvmpipe computes from float uv
// interpolated by the rasteriser (1e-4 of a texel off the ray's exact hit: up to 3e-4 of a
// pixel's value at a patch's edge), so what is compared is the data, the projection and the uv.
bool uniformTexels(const prt::PrtDrawData& d, const Hit& hit) {
  const prt::PrtTextureSource& texture = *d.textures[static_cast<std::size_t>(d.vertexMaterial[d.indices[hit.triangle]])];
  const int w = texture.width(), h = texture.height();
  const glm::dvec2 uv = hitUv(d, hit);
  const int x0 = static_cast<int>(std::floor((uv.x - std::floor(uv.x)) * w - 0.5));
  const int y0 = static_cast<int>(std::floor((uv.y - std::floor(uv.y)) * h - 0.5));
  for (const Eigen::MatrixXd& map : d.reflectanceMaps) {
    prt::PrtTexelProjector projector(texture, map);
    auto texel = [&](int dx, int dy) { return projector.texel(((x0 + dx) % w + w) % w, ((y0 + dy) % h + h) % h); };
    const shared::PrtReflectance first = texel(0, 0);
    for (glm::ivec2 o : {glm::ivec2(1, 0), glm::ivec2(0, 1), glm::ivec2(1, 1)}) {
      const shared::PrtReflectance other = texel(o.x, o.y);
      for (int j = 0; j < projector.basisCount(); ++j)
        if (other.r[j] != first.r[j]) return false;
    }
  }
  return true;
}

// Under water (`sets`: a water section) the textured materials take ρ from R̂'s projection at the
// nodes (shared/prt_medium.glsl), dimmed; the twin does the same, and the lighting pass's twin
// adds the water's in-scattering below them.
void expectMagnifiedTexelsAgreeWithTheTwin(const PrtModeCase& mode, const std::vector<std::string>& sets) {
  gpu::HeadlessContext context;
  Scene scene = loadScene(std::filesystem::path(PRISM_SCENES_DIR) / "prt_textures.json", sets);
  scene.techniques.find<prt::PrtSection>()->mode = mode.mode;
  scene.camera.position = glm::vec3(3.0f, 1.4f, 6.4f);
  scene.camera.target = glm::vec3(3.0f, 0.8f, 4.2f);
  const FrameSettings settings = prtTwinSettings(mode, 480, 270);
  Renderer renderer(scene, cachedTestTable(), settings);
  renderer.renderFrame();
  auto data = std::dynamic_pointer_cast<const prt::PrtDrawData>(renderer.techniquePass(prt::PrtSection::kKey)->readTexels());
  ASSERT_TRUE(data);
  ASSERT_EQ(data->medium.has_value(), !sets.empty());
  ASSERT_EQ(data->textures.size(), 3u);
  for (const auto& texture : data->textures) ASSERT_TRUE(texture);
  std::vector<float> lit = gpu::readTexture2DFloat(renderer.accumulation(), 4);
  LightingTwin lighting(renderer, cachedTestTable());

  const int w = settings.width, h = settings.height;
  std::set<int> materials;
  // Float sums against double, as for the untextured objects (prt_pass_test.cpp).
  constexpr double kSums = 1e-4;
  double worst = 0.0, worstShare = 0.0;
  int compared = 0;
  forRandomInteriorPixels(*data, renderer.cameraTransform(), w, h, 16, 600, [&](int x, int y, const Hit& hit) {
    if (texelFootprint(*data, renderer.cameraTransform(), hit, x, y, w, h) > 0.75 || !uniformTexels(*data, hit)) return;
    const glm::dvec3 below = lighting.at(x, y);
    const glm::dvec3 expected = below + cpuTristimulus(*data, hit, renderer.cameraTransform().position);
    const std::size_t i = static_cast<std::size_t>(y * w + x);
    const glm::dvec3 actual(lit[4 * i], lit[4 * i + 1], lit[4 * i + 2]);
    const double scale = std::max({std::abs(expected.x), std::abs(expected.y), std::abs(expected.z)});
    // The rasteriser snaps vertices to 1/256 of a pixel (llvmpipe's subpixel precision), moving
    // what a pixel interpolates by up to half that step: the twin's change over such a step, on
    // this bumpy, self-shadowing field, is part of the bound.
    double snap = 0.0;
    for (glm::dvec2 o : {glm::dvec2(1.0 / 512.0, 0.0), glm::dvec2(0.0, 1.0 / 512.0)}) {
      auto [origin, dir] = pixelRay(renderer.cameraTransform(), x + 0.5 + o.x, y + 0.5 + o.y, w, h);
      std::optional<Hit> moved = intersect(*data, origin, dir);
      if (moved) snap += glm::length(below + cpuTristimulus(*data, *moved, renderer.cameraTransform().position) - expected) / scale;
    }
    const double error = glm::length(actual - expected) / scale;
    worst = worstOf(worst, error);
    worstShare = worstOf(worstShare, error / (kSums + snap));
    materials.insert(data->vertexMaterial[data->indices[hit.triangle]]);
    ++compared;
  });
  std::printf("textured PRT %s (frame %s)%s: %d magnified pixels of %zu materials; relative error max %.3g, "
              "at most %.2f of its bound\n",
              std::string(prt::prtModeName(mode.mode)).c_str(), std::string(renderModeName(mode.frameMode)).c_str(),
              sets.empty() ? "" : " under water", compared, materials.size(), worst, worstShare);
  EXPECT_GT(compared, 100);
  EXPECT_EQ(materials.size(), 3u);
  EXPECT_LE(worstShare, 1.0);
}

TEST_P(PrtTexturedParity, MagnifiedTexelsAgreeWithTheTwin) { expectMagnifiedTexelsAgreeWithTheTwin(GetParam(), {}); }

TEST_P(PrtTexturedParity, MagnifiedTexelsAgreeWithTheTwinUnderWater) {
  expectMagnifiedTexelsAgreeWithTheTwin(GetParam(), {R"(water={"type": "IB", "depth": 1})"});
}

INSTANTIATE_TEST_SUITE_P(Modes, PrtTexturedParity, prtModeCases(), prtModeCaseName);

// The scene's lights (here the spectral sky's sun) are the lighting pass's, which reads no spectral
// texture: the loader refuses such a material under them (tests/bad_input), and so does the pass
// when an edit brings them together, in one line naming the material, before anything is drawn.
TEST(PrtTextured, ASpectralTextureUnderASceneLightIsRefused) {
  gpu::HeadlessContext context;
  Scene scene = loadScene(std::filesystem::path(PRISM_SCENES_DIR) / "prt_sky.json");
  const Scene textured = loadScene(std::filesystem::path(PRISM_SCENES_DIR) / "prt_textures.json");
  for (const Mesh& mesh : scene.meshes)
    if (mesh.technique == "prt") scene.materials.at(static_cast<std::size_t>(mesh.material)).spectralTexture = textured.materials[0].spectralTexture;
  FrameSettings settings;
  settings.width = 32;
  settings.height = 18;
  Renderer renderer(scene, cachedTestTable(), settings);
  try {
    renderer.renderFrame();
    FAIL() << "rendered";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("prt_sky.json: /materials/"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("has a spectral texture, which the scene's lights cannot read"), std::string::npos)
        << e.what();
    EXPECT_EQ(std::string(e.what()).find('\n'), std::string::npos);
  }
}

}  // namespace
}  // namespace prism::render
