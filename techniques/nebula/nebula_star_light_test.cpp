// The nebula's stars as lights of the scene's surfaces (nebula_section.h, shared/nebula_lighting.glsl):
// their radiant intensity in world units is the one the nebula's own light implies, and the dust's
// dimming the lighting pass reads from the star-depth grid holds to the exact column along the
// segment from the surface to the star (the reference).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <random>

#include "spectral/colour_space.h"
#include "spectral/observer.h"
#include "techniques/nebula/nebula_cpu_twin.h"
#include "techniques/nebula/nebula_precomputed.h"
#include "techniques/nebula/nebula_section.h"

namespace prism::nebula {
namespace {

constexpr double kPi = std::numbers::pi;

// A star in a cube of uniform grey dust that scatters but does not dim, seen side-on by a
// one-pixel camera along z at 0.3 of the cube from the star: the CPU marcher's reference (CIE 1931
// filters) times the section's intensity is the luminance of the light the dust scatters; the same
// from the star's radiant intensity I(λ) in the world is 683 ∫ ȳ ∫ σ/(4π)·I(λ)/r² ds dλ, which for a
// cube of side `size` is luminousIntegral(I)·σ₁/(4π·size²)·(2/a)·atan(1/(2a)), a = 0.3.
TEST(NebulaStarLight, ItsRadiantIntensityIsTheOneTheNebulasLightImplies) {
  NebulaSection section;
  section.boxSize = 4.0f;
  section.intensity = 250.0f;
  section.model.extinction = 0.0;
  section.model.scattering = 1.0;
  section.model.filters = "cie1931";
  section.model.stars = {{{0.5, 0.5, 0.5}, 6500.0, 2.0}};
  section.model.camera = {{0.2, 0.5, -1.0}, {0.2, 0.5, 0.5}, 1.0, 1, 1};
  DensityGrid uniform{8, 8, 8, std::vector<float>(512, 1.0f)};
  section.density = std::make_shared<DeferredDensity>(uniform);
  RenderSettings settings;
  settings.method = Method::Reference;
  settings.steps = 4000;
  settings.emissionLines = false;
  const NebulaRenderer renderer(section.fullModel(), settings);
  const double marched = section.intensity * renderer.render(settings).pixels[0].y;

  const double a = 0.3, size = section.boxSize;
  const double expected = luminousIntegral(section.starRadiantIntensity(section.model.stars[0])) *
                          section.model.scattering / (4.0 * kPi * size * size) * (2.0 / a) * std::atan(0.5 / a);
  std::printf("dust lit by a star: %.6g cd/m² marched, %.6g from the star's radiant intensity (ratio %.5f)\n", marched,
              expected, marched / expected);
  EXPECT_NEAR(marched / expected, 1.0, 0.01);  // the nebula's ȳ is a fit, within 0.6 % of its peak
}

// The exact optical depth g (µm) from p to the star: C_T·κ·∫ ρ over the segment's part in the
// cube, by the midpoint rule at 1/4000 of the cube's side.
double exactColumn(const DensityGrid& density, double extinction, const glm::dvec3& p, const glm::dvec3& star) {
  const glm::dvec3 d = star - p;
  const double length = glm::length(d);
  const int n = std::max(1, static_cast<int>(std::ceil(length * 4000.0)));
  double column = 0.0;
  for (int i = 0; i < n; ++i) column += density.sample(p + d * ((i + 0.5) / n));
  return kCtUm * extinction * column * length / n;
}

// Over the example field's density (64³) with its three stars and one outside the cube, at random
// points in the cube and around it, more than two voxels from the star: the depth the lighting
// pass reads (the grid at the point, or where the segment enters the cube; none where it misses)
// against the exact column. Its transmittance at 450 nm, e^(−g/λ), the most dimmed of the visible
// band's, stays within 3 % of the exact one's inside the cube and 5 % outside (measured: 2.4 %,
// 4.5 %, 0.25 % on average): the grid's error is the precomputation's — its columns by the midpoint
// rule at half a voxel, trilinear between voxel centres, constant between the faces and the outer
// centres — which the nebula's own march shares; outside, the largest is a short path that
// crosses a corner of the cube towards a star beyond it.
TEST(NebulaStarLight, TheDustDimsItAsTheExactColumnDoes) {
  NoiseParameters noise;
  noise.resolution = 64;
  noise.amplitude = 1.6;
  noise.bias = 0.35;
  noise.seed = 7;
  NebulaModel model;
  model.density = generateFbm(noise);
  model.extinction = 3.0;
  model.stars = {{{0.5, 0.55, 0.45}, 25000.0, 1.0}, {{0.32, 0.42, 0.6}, 6000.0, 0.4}, {{0.66, 0.36, 0.38}, 12000.0, 0.5},
                 {{1.5, 0.5, 0.5}, 9000.0, 1.0}};
  RenderSettings settings;
  settings.emissionLines = false;
  const NebulaRenderer renderer(model, settings);
  const NebulaPrecomputed& pre = renderer.precomputed();

  std::mt19937 random(11);
  std::uniform_real_distribution<double> inside(0.0, 1.0), around(-0.6, 1.6);
  double worstInside = 0.0, worstOutside = 0.0, meanError = 0.0, deepest = 0.0;
  int compared = 0, missed = 0;
  for (int i = 0; i < 600; ++i) {
    const bool in = i < 300;
    const glm::dvec3 p = in ? glm::dvec3(inside(random), inside(random), inside(random))
                            : glm::dvec3(around(random), around(random), around(random));
    for (std::size_t s = 0; s < model.stars.size(); ++s) {
      const glm::dvec3 star = model.stars[s].position;
      if (glm::length(p - star) < 2.0 / noise.resolution) continue;
      glm::vec3 at;
      float g = 0.0f;
      if (shared::nebulaStarDepthPoint(glm::vec3(p), glm::vec3(star), at))
        pre.starDepth[s].sample(glm::dvec3(at), &g);
      else
        ++missed;
      const double exact = exactColumn(model.density, model.extinction, p, star);
      const double error = std::abs(std::exp(-(g - exact) / 0.45) - 1.0);
      (in ? worstInside : worstOutside) = std::max(in ? worstInside : worstOutside, error);
      meanError += error;
      deepest = std::max(deepest, exact);
      ++compared;
    }
  }
  meanError /= compared;
  std::printf("star light's transmittance at 450 nm against the exact column, %d point–star pairs (%d missing the "
              "cube), g up to %.2f µm: max relative error %.3g inside the cube, %.3g outside, mean %.3g\n",
              compared, missed, deepest, worstInside, worstOutside, meanError);
  EXPECT_GT(missed, 10);
  EXPECT_GT(deepest, 1.0);
  EXPECT_LE(worstInside, 0.03);
  EXPECT_LE(worstOutside, 0.05);
  EXPECT_LE(meanError, 0.005);
}

// The block the lighting pass reads: the box, each star's world position, its intensity at the
// batches' wavelengths (RGB mode: its linear RGB); no stars when `light_surfaces` is off.
TEST(NebulaStarLight, TheBlockCarriesEachStarAtTheFramesWavelengths) {
  NebulaSection section;
  section.boxMin = glm::vec3(-2.0f, -1.0f, 0.0f);
  section.boxSize = 4.0f;
  section.intensity = 100.0f;
  section.model.stars = {{{0.5, 0.25, 1.0}, 9000.0, 1.0}, {{0.0, 0.0, 0.0}, 3000.0, 0.5}};
  shared::GpuBatch batches[2]{};
  batches[0].lambdaNm = glm::vec4(400.0f, 500.0f, 600.0f, 700.0f);
  batches[1].lambdaNm = glm::vec4(450.0f, 550.0f, 650.0f, 750.0f);
  FramePackInput input;
  input.batches = batches;
  const TechniqueBlock block = section.pack(input);
  const auto constants = block.constantsAs<shared::NebulaLightConstants>();
  EXPECT_EQ(constants.starCount, 2);
  EXPECT_EQ(constants.boxMinSize, glm::vec4(-2.0f, -1.0f, 0.0f, 4.0f));
  EXPECT_EQ(block.dataCount<glm::vec4>(), 6u);
  EXPECT_EQ(block.dataAt<glm::vec4>(static_cast<std::size_t>(shared::nebulaStarPositionIndex(0, 2))),
            glm::vec4(0.0f, 0.0f, 4.0f, 0.0f));
  const Spectrum cool = section.starRadiantIntensity(section.model.stars[1]);
  const glm::vec4 packed = block.dataAt<glm::vec4>(static_cast<std::size_t>(shared::nebulaStarSpectrumIndex(1, 1, 2)));
  EXPECT_NEAR(packed.y, cool.at(550.0), 1e-6 * cool.at(550.0));
  EXPECT_GT(packed.w, packed.x);  // 3000 K: redder

  const RgbColourSpace& srgb = colourSpace("srgb");
  input.rgbMode = true;
  input.colourSpace = &srgb;
  const TechniqueBlock rgb = section.pack(input);
  const glm::vec4 warm = rgb.dataAt<glm::vec4>(static_cast<std::size_t>(shared::nebulaStarSpectrumIndex(1, 0, 1)));
  EXPECT_GT(warm.x, warm.z);
  const Eigen::Vector3d xyz = srgb.rgbToXyz * Eigen::Vector3d(warm.x, warm.y, warm.z);
  EXPECT_NEAR(xyz.y(), luminousIntegral(cool), 1e-4 * luminousIntegral(cool));

  section.lightSurfaces = false;
  EXPECT_EQ(section.pack(input).constantsAs<shared::NebulaLightConstants>().starCount, 0);
}

}  // namespace
}  // namespace prism::nebula
