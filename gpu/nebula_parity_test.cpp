// nebula_integrals.glsl on the GPU vs the same file compiled as C++ in float (STYLE.md §4).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "gpu/gpu_test_support.h"
#include "shared_cpp.h"

namespace prism::shared {
using glm::log;
#include "nebula_integrals.glsl"
}  // namespace prism::shared

namespace prism::gpu {
namespace {

using glm::vec4;
using testing::GpuTest;
using testing::ParityReport;

TEST_F(GpuTest, NebulaIntegralsMatchCpu) {
  testing::InputGenerator gen(0x0eb01a00u);
  std::vector<vec4> a, b;
  // u log-spaced over [1e-6, 80] (E₁'s range in a render), x ∈ [0, 1] µm, intervals of the
  // visible band at least 50 nm wide; polynomial coefficients in [0, 1].
  for (float u : {1e-6f, 0.5f, 1.0f, std::nextafter(1.0f, 2.0f), 2.0f, 80.0f})
    a.push_back(vec4(u, 0.0f, 0.38f, 0.78f)), b.push_back(vec4(1.0f));
  while (a.size() < 4096) {
    float u = std::pow(10.0f, gen.uniform(-6.0f, 1.9f));
    float x = gen.unit() < 0.1f ? 0.0f : gen.unit();
    float l0 = gen.uniform(0.38f, 0.73f), l1 = gen.uniform(l0 + 0.05f, 0.78f);
    a.push_back(vec4(u, x, l0, l1));
    b.push_back(vec4(gen.unit(), gen.unit(), gen.unit(), gen.unit()));
  }
  Program kernel = testing::parityKernel("nebula_integrals.comp");
  std::vector<vec4> gpu = testing::runParityKernel<vec4>(kernel, std::span<const vec4>(a), std::span<const vec4>(b));
  // E₁ (GLSL 4.50 §4.7.1): below u = 1, log within 2^-21 absolute on [0.5, 2] where E₁ ≥ 0.2
  // (≤ 2.4e-6 relative) plus the series' 16 roundings a side; above, exp(−u) within 3 + 2u ULP,
  // ≤ 163 ULP ≈ 1.9e-5 at u = 80, plus the continued fraction's 24 steps: 2.5e-5 relative.
  ParityReport e1("nebulaE1", {0.0, 2.5e-5, 0});
  // The integrals: GLSL's exp (≤ 3 + 2·|x/λ| ≤ 9 ULP here) and log (within 2⁻²¹ absolute in E₁'s
  // series, E₂ = e^(−u) − u·E₁ ≥ 0.148 below u = 1), amplified by the bounds' cancellation
  // λ/(λ₁ − λ₀) ≤ 16 (the exponential integrals' recurrences add no more, nebula_test): 2e-4 relative.
  ParityReport expIntegral("nebulaExpIntegral", {0.0, 2e-4, 0});
  ParityReport polyIntegral("nebulaPolyExpIntegral", {0.0, 2e-4, 0});
  ParityReport moments("nebulaExpMoments.w", {0.0, 2e-4, 0});
  for (std::size_t i = 0; i < a.size(); ++i) {
    const vec4& v = a[i];
    char input[160];
    std::snprintf(input, sizeof input, "(u %.9g, x %.9g, [%.9g, %.9g])", v.x, v.y, v.z, v.w);
    e1.compare(gpu[i].x, shared::nebulaE1(v.x), input);
    expIntegral.compare(gpu[i].y, shared::nebulaExpIntegral(v.y, v.z, v.w), input);
    polyIntegral.compare(gpu[i].z, shared::nebulaPolyExpIntegral(b[i], 0.5f * b[i], v.y, v.z, v.w), input);
    moments.compare(gpu[i].w, shared::nebulaExpMoments(v.y, vec4(0.0f, 0.2f, 0.4f, 0.6f), v.z, v.w).w, input);
  }
  e1.finish();
  expIntegral.finish();
  polyIntegral.finish();
  moments.finish();
}

// E₂…E₉ over u ∈ {0} ∪ [1e-6, 80] and at the start orders' edges, so that every start order (E₂
// below u = 2, the continued fraction at ⌊u⌋ + 1 up to 9) and both directions of the recurrence
// run in GLSL.
TEST_F(GpuTest, NebulaExponentialIntegralsMatchCpu) {
  testing::InputGenerator gen(0x0eb01a02u);
  std::vector<float> us = {0.0f, 1e-6f, 1.0f, std::nextafter(1.0f, 2.0f), 2.0f, 2.5f, 7.99f, 8.0f, 8.01f, 9.0f, 20.0f, 80.0f};
  while (us.size() < 2048) us.push_back(std::pow(10.0f, gen.uniform(-6.0f, 1.9f)));
  std::vector<vec4> a, b;
  for (float u : us)
    for (float half : {0.0f, 1.0f}) a.push_back(vec4(u, half, 0.0f, 0.0f)), b.push_back(vec4(0.0f));
  Program kernel = testing::parityKernel("nebula_exponential_integrals.comp");
  std::vector<vec4> gpu = testing::runParityKernel<vec4>(kernel, std::span<const vec4>(a), std::span<const vec4>(b));
  // GLSL's exp within 3 + 2·u ULP (≤ 163 ULP ≈ 1.9e-5 at u = 80), its log within 2⁻²¹ absolute in
  // E₁'s series below u = 1 (E₂ ≥ 0.148 there: ≤ 3.2e-6 relative), carried by recurrence steps
  // that multiply an error by at most 1, plus their own roundings: 3e-5 relative.
  ParityReport report("nebulaExponentialIntegrals", {0.0, 3e-5, 0});
  for (std::size_t i = 0; i < a.size(); ++i) {
    vec4 lo, hi;
    shared::nebulaExponentialIntegrals(a[i].x, lo, hi);
    const vec4 cpu = a[i].y > 0.5f ? hi : lo;
    for (int m = 0; m < 4; ++m) {
      char input[96];
      std::snprintf(input, sizeof input, "(u %.9g, E%d)", a[i].x, (a[i].y > 0.5f ? 6 : 2) + m);
      report.compare(gpu[i][m], cpu[m], input);
    }
  }
  report.finish();
}

TEST_F(GpuTest, NebulaNegativePowersMatchCpu) {
  testing::InputGenerator gen(0x0eb01a01u);
  std::vector<vec4> a, b;
  // Optical depth y = 10x ∈ [0, 10] µm (both of the integrals' forms), intervals of the visible
  // band at least 25 nm wide (the CIE fits' pieces); a cubic's coefficients in [0, 1].
  for (float x : {0.0f, 0.02f, 0.1f, 1.0f}) a.push_back(vec4(0.0f, x, 0.38f, 0.78f)), b.push_back(vec4(1.0f));
  while (a.size() < 4096) {
    float x = gen.unit() < 0.1f ? 0.0f : gen.unit();
    float l0 = gen.uniform(0.38f, 0.755f), l1 = gen.uniform(l0 + 0.025f, 0.78f);
    a.push_back(vec4(0.0f, x, l0, l1));
    b.push_back(vec4(gen.unit(), gen.unit(), gen.unit(), gen.unit()));
  }
  Program kernel = testing::parityKernel("nebula_wien.comp");
  std::vector<vec4> gpu = testing::runParityKernel<vec4>(kernel, std::span<const vec4>(a), std::span<const vec4>(b));
  // GLSL's exp within 3 + 2·|y/λ| ≤ 56 ULP (y ≤ 10.3 µm, λ ≥ 0.38), amplified by the bounds'
  // cancellation λ/(λ₁ − λ₀) ≤ 31 and the by-parts form's ≤ 4 steps: 2e-4 relative (float
  // against quadrature: ≤ 1e-5, nebula_test).
  ParityReport wien("nebulaWienPolyIntegral", {0.0, 2e-4, 0});
  ParityReport wienStar("nebulaWienPolyIntegral, y + B", {0.0, 2e-4, 0});
  ParityReport five("nebulaInversePowerExpIntegrals k=5", {0.0, 2e-4, 0});
  ParityReport two("nebulaInversePowerExpIntegrals k=2", {0.0, 2e-4, 0});
  for (std::size_t i = 0; i < a.size(); ++i) {
    const vec4& v = a[i];
    char input[160];
    std::snprintf(input, sizeof input, "(y %.9g, [%.9g, %.9g])", 10.0f * v.y, v.z, v.w);
    const float y = 10.0f * v.y;
    const vec4 powers = shared::nebulaInversePowerExpIntegrals(y, v.z, v.w);
    wien.compare(gpu[i].x, shared::nebulaWienPolyIntegral(b[i], y, v.z, v.w), input);
    wienStar.compare(gpu[i].y, shared::nebulaWienPolyIntegral(b[i], y + 0.29f, v.z, v.w), input);
    five.compare(gpu[i].z, powers.x, input);
    two.compare(gpu[i].w, powers.w, input);
  }
  wien.finish();
  wienStar.finish();
  five.finish();
  two.finish();
}

}  // namespace
}  // namespace prism::gpu
