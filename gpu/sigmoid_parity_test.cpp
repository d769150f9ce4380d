// sigmoid.glsl on the GPU vs the same file compiled as C++ (STYLE.md §4).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <string>
#include <vector>

#include "gpu/gpu_test_support.h"
#include "shared_cpp.h"

namespace prism::shared {
#include "sigmoid.glsl"
}

namespace prism::gpu {
namespace {

using glm::vec4;
using testing::GpuTest;
using testing::kUlp;
using testing::ParityReport;
using testing::Tolerance;

constexpr float kInf = std::numeric_limits<float>::infinity();
constexpr double kUnitRoundoff = 0x1p-24;  // half an ULP of 1

// Arguments of S across every magnitude, both signs, and the edges: 0, ±1, the 1e9 cut-over to
// the limits, where x² would overflow (|x| > 1.8e19), the largest float and ±∞.
std::vector<float> sigmoidArguments() {
  std::vector<float> x{0.0f,
                       -0.0f,
                       1.0f,
                       -1.0f,
                       1e-30f,
                       -1e-30f,
                       1e9f,
                       -1e9f,
                       1.0001e9f,
                       -1.0001e9f,
                       1e19f,
                       -1e19f,
                       2e19f,
                       -2e19f,
                       std::numeric_limits<float>::max(),
                       -std::numeric_limits<float>::max(),
                       kInf,
                       -kInf};
  testing::InputGenerator gen(0x519e01du);
  while (x.size() < 4096) {
    float magnitude = std::pow(10.0f, gen.uniform(-6.0f, 6.0f));
    x.push_back(gen.unit() < 0.5f ? magnitude : -magnitude);
  }
  return x;
}

std::string describe(float x) {
  char text[64];
  std::snprintf(text, sizeof text, "(%.9g)", x);
  return text;
}

void checkUnary(const std::string& name, float (*cpu)(float), Tolerance tolerance) {
  std::vector<float> x = sigmoidArguments();
  Program kernel = testing::parityKernel("sigmoid.comp", {{"SIGMOID_FUNCTION", name}});
  std::vector<float> gpu = testing::runParityKernel<float>(kernel, std::span<const float>(x));
  ParityReport report(name, tolerance);
  for (std::size_t i = 0; i < x.size(); ++i)
    report.compare(gpu[i], cpu(x[i]), name + describe(x[i]));
  report.finish();
}

// S is a reflectance in (0, 1), so its error is absolute: q = x / (2·√(1 + x²)) has |q| < 1/2
// and carries √ (GLSL: 1/inversesqrt, 2 + 2.5 ULP), ÷ (2.5 ULP) and 1 + x² (0.5 ULP, halved by
// √) on the GPU, ≤ 2 ULP on the CPU; then 0.5 + q rounds once per side.
constexpr double kSigmoidTolerance = (7.25 + 2.0) * kUlp * 0.5 + 2.0 * kUnitRoundoff;

// Tolerance: 6.7e-7 absolute (kSigmoidTolerance). Reason: above.
TEST_F(GpuTest, SigmoidMatchesCpuIncludingInfinities) {
  checkUnary("sigmoid", shared::sigmoid, {kSigmoidTolerance, 0.0, 0});
}

// Tolerance: 10 ULP, or FLT_MIN absolute. Reason: 0.5 / (s·√s) is a √ (GLSL: 4.5 ULP), a
// product and a division (2.5 ULP) on the GPU, 1.5 ULP on the CPU; results below FLT_MIN are
// denormals, which GLSL lets an implementation flush to zero.
TEST_F(GpuTest, SigmoidDerivativeMatchesCpuIncludingInfinities) {
  checkUnary("sigmoidDerivative", shared::sigmoidDerivative,
             {std::numeric_limits<float>::min(), 0.0, 10});
}

// Coefficients as Jakob–Hanika tables produce them: a random quadratic in t = (λ − 360)/470,
// whose expansion in λ (nm) has large terms that cancel; plus coefficients whose polynomial
// overflows to ±∞ (S = 1 or 0) and the all-zero polynomial (S = 0.5). Wavelengths cover
// 360–830 nm, so upsampledReflectance4's clamp to [380, 730] nm is exercised at both ends.
void checkSpectrum4(const std::string& name, vec4 (*cpuSpectrum)(const glm::vec3&, const vec4&),
                    float minNm, float maxNm) {
  testing::InputGenerator gen(0x5bec7a4u);
  std::vector<vec4> coeffs, lambdas;
  coeffs.push_back(vec4(1e38f, 0.0f, 0.0f, 0.0f));
  coeffs.push_back(vec4(-1e38f, 1e38f, 0.0f, 0.0f));
  coeffs.push_back(vec4(0.0f));
  while (coeffs.size() < 4096) {
    double a2 = gen.uniform(-60.0f, 60.0f), a1 = gen.uniform(-60.0f, 60.0f),
           a0 = gen.uniform(-30.0f, 30.0f);
    double s = 1.0 / 470.0, o = -360.0 / 470.0;  // t = s·λ + o
    coeffs.push_back(vec4(static_cast<float>(a2 * s * s),
                          static_cast<float>(2 * a2 * s * o + a1 * s),
                          static_cast<float>(a2 * o * o + a1 * o + a0), 0.0f));
  }
  for (std::size_t i = 0; i < coeffs.size(); ++i)
    lambdas.push_back(vec4(gen.uniform(360.0f, 830.0f), gen.uniform(360.0f, 830.0f),
                           gen.uniform(360.0f, 830.0f), i % 7 == 0 ? 360.0f : 830.0f));

  Program kernel = testing::parityKernel("sigmoid_spectrum4.comp", {{"SPECTRUM4", name}});
  std::vector<vec4> gpu = testing::runParityKernel<vec4>(kernel, std::span<const vec4>(coeffs),
                                                         std::span<const vec4>(lambdas));
  // Tolerance: sigmoid's (6.7e-7) plus, per value, S'(x) times the rounding bound of the
  // Horner polynomial on both sides, 2·γ4·(|c0|λ² + |c1|λ + |c2|) (Higham 2002, Accuracy and
  // Stability of Numerical Algorithms, Eq. 5.3: γ2n for degree n, unfused). Reason: the terms reach 1e3 and
  // cancel to x ≈ ±10, so x's error is set by the terms, not by x; S' ≤ 1/2 damps it.
  ParityReport report(name, {kSigmoidTolerance, 0.0, 0});
  for (std::size_t i = 0; i < coeffs.size(); ++i) {
    glm::vec3 c(coeffs[i]);
    vec4 cpu = cpuSpectrum(c, lambdas[i]);
    for (int k = 0; k < 4; ++k) {
      double l = std::clamp(lambdas[i][k], minNm, maxNm);
      double terms = std::abs(c.x) * l * l + std::abs(c.y) * l + std::abs(c.z);
      double x = (static_cast<double>(c.x) * l + c.y) * l + c.z;
      double slope = 0.5 / std::pow(1.0 + x * x, 1.5);
      double gamma4 = 4.0 * kUnitRoundoff / (1.0 - 4.0 * kUnitRoundoff);
      char input[160];
      std::snprintf(input, sizeof input, "%s((%.9g, %.9g, %.9g), %.9g)", name.c_str(), c.x, c.y,
                    c.z, lambdas[i][k]);
      report.compare(gpu[i][k], cpu[k], input,
                     std::isfinite(terms) ? slope * 2.0 * gamma4 * terms : 0.0);
    }
  }
  report.finish();
}

TEST_F(GpuTest, SigmoidSpectrum4MatchesCpu) {
  checkSpectrum4("sigmoidSpectrum4", shared::sigmoidSpectrum4, 0.0f, 1e4f);
}

TEST_F(GpuTest, UpsampledReflectance4MatchesCpu) {
  checkSpectrum4("upsampledReflectance4", shared::upsampledReflectance4, shared::kReflectanceMinNm,
                 shared::kReflectanceMaxNm);
}

}  // namespace
}  // namespace prism::gpu
