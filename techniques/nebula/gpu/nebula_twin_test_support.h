// The nebula's GPU tests' small nebula, and what they hold the GPU marcher to: its CPU twin,
// within a bound derived from float rounding (the marcher's tests and the renderer pass's,
// render/nebula_pass_test.cpp).
//
// The twin bound, per pixel and channel, derived from float rounding. Both marchers read the same
// uploaded arrays at the same samples with the same shared formulas (nebula_march.glsl,
// nebula_integrals.glsl) and the same float table of coefficients; the GPU rounds in float what
// the CPU keeps in double: the ray's geometry, the camera's depth, and each pixel's moment sums
// Σ w·cⱼ over ≤ N steps, then the finish's Σ Wⱼ·mⱼ over G·card terms (G stars or 2D elements)
// and its L lines' light times their responses. Each addition and product rounds by ≤ 2⁻²⁴ of the
// magnitudes involved, so
//   |GPU − CPU| ≤ (N + G·card + L)·2⁻²⁴·(Σⱼ |Wⱼ·mⱼ| + |CPU| + 1 % of the channel's peak),
// with Σ|Wⱼ·mⱼ| computed per pixel from the GPU's own moments (it is what the rounding scales
// with; |CPU| stands for the lines' term, and 1 % of the peak for a sample that the ray's float
// geometry moves by ~1e-7 of the cube). On the twin nebula Σ|Wⱼ·mⱼ| is 1–3× the channel, since
// the march accumulates coefficients on the orthonormal basis (nebula_precomputed.h says why).
// The reference has no moments: it adds N·G sums of K node terms (K the most nodes a channel
// has) into the colour, so N·G + K terms take the place of N + G·card; the lines' L stay.
#pragma once

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <string>
#include <utility>
#include <vector>

#include "core/worst_of.h"
#include "techniques/nebula/gpu/nebula_gpu_marcher.h"
#include "techniques/nebula/nebula_test_cloud.h"

namespace prism::nebula {

// The tests' nebula: the small cloud with continuum emission and three line groups.
inline NebulaModel smallNebula(std::string filters, int starCount) {
  NebulaModel m = smallCloud(std::move(filters), starCount);
  m.emission = 0.002;
  m.lineGroups = {{"H I Balmer (case B)", 1.0}, {"[O III] doublet", 0.8}, {"[S II] doublet", 0.4}};
  return m;
}

// The methods that add into the colour directly (no moments) round N·G sums of K terms each: the
// reference K nodes, pre-integration the four Catmull–Rom taps. 0 for the others (twinRatio's
// N + G·card).
inline std::size_t directTerms(const NebulaRenderer& renderer, const RenderSettings& s, Method method, int steps, int stars) {
  std::size_t k = 0;
  if (method == Method::Reference) {
    for (const auto& channel : renderer.referenceNodes(s).lambdaUm) k = std::max(k, channel.size());
  } else if (method == Method::PreIntegration) {
    k = 4;
  } else {
    return 0;
  }
  return static_cast<std::size_t>(steps * stars) + k;
}

// The largest |GPU − CPU| over its bound (above), over pixels and channels: ≤ 1 passes.
inline double twinRatio(const NebulaImage& gpuImage, const NebulaImage& cpu, const NebulaGpuMarcher& gpu, int steps,
                 std::size_t referenceTerms = 0) {
  EXPECT_EQ(gpuImage.pixels.size(), cpu.pixels.size());
  const std::vector<float> moments = gpu.readMoments();
  const std::vector<float>& weights = gpu.finishWeights();
  const std::size_t pixels = cpu.pixels.size();
  const auto card = static_cast<std::size_t>(gpu.card()), groups = static_cast<std::size_t>(gpu.groups());
  const double rounding =
      static_cast<double>((referenceTerms > 0 ? referenceTerms : static_cast<std::size_t>(steps) + groups * card) +
                          static_cast<std::size_t>(gpu.lines())) * 0x1p-24;
  double worst = 0.0;
  for (int c = 0; c < 3; ++c) {
    double peak = 0.0;
    for (const auto& p : cpu.pixels) peak = std::max(peak, std::abs(static_cast<double>(p[c])));
    for (std::size_t i = 0; i < pixels; ++i) {
      double magnitude = std::abs(static_cast<double>(cpu.pixels[i][c])) + 0.01 * peak;
      for (std::size_t g = 0; g < groups; ++g)
        for (std::size_t j = 0; j < card; ++j)
          magnitude += std::abs(static_cast<double>(weights[(g * 3 + static_cast<std::size_t>(c)) * card + j]) *
                                moments[(g * card + j) * pixels + i]);
      worst = worstOf(worst, std::abs(gpuImage.pixels[i][c] - cpu.pixels[i][c]) / (rounding * magnitude));
    }
  }
  return worst;
}

// The largest |a − b| / max(|b|, 1 % of b's channel peak): the goldens' and the finish's measure.
inline double relativeError(const NebulaImage& a, const NebulaImage& b) {
  double worst = 0.0;
  for (int c = 0; c < 3; ++c) {
    double peak = 0.0;
    for (const auto& p : b.pixels) peak = std::max(peak, std::abs(static_cast<double>(p[c])));
    for (std::size_t i = 0; i < b.pixels.size(); ++i)
      worst = worstOf(worst, std::abs(a.pixels[i][c] - b.pixels[i][c]) /
                                  std::max(std::abs(static_cast<double>(b.pixels[i][c])), 0.01 * peak));
  }
  return worst;
}

inline double peakOf(const NebulaImage& image) {
  double peak = 0.0;
  for (const auto& p : image.pixels) peak = std::max({peak, static_cast<double>(p.x), static_cast<double>(p.y), static_cast<double>(p.z)});
  return peak;
}

}  // namespace prism::nebula
