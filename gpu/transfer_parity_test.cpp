// transfer.glsl on the GPU vs the same file compiled as C++ (STYLE.md §4).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <limits>
#include <string>
#include <vector>

#include "gpu/gpu_test_support.h"
#include "shared_cpp.h"

namespace prism::shared {
#include "transfer.glsl"
}

namespace prism::gpu {
namespace {

using glm::vec3;
using glm::vec4;
using testing::glslPowRelativeError;
using testing::GpuTest;
using testing::kUlp;
using testing::ParityReport;

// Signals in [-0.1, 1.1] (out-of-range ones are clamped or extrapolated by the formulas), the
// branch points of both curves and their float neighbours, 0, 1 and tiny values.
std::vector<vec4> signals() {
  std::vector<float> edges{0.0f,
                           -0.0f,
                           1.0f,
                           1e-7f,
                           -1e-7f,
                           1e-30f,
                           0.0031308f,
                           0.04045f,
                           0.018053968510807f,
                           4.5f * 0.018053968510807f,
                           0.5f};
  std::vector<float> values;
  for (float e : edges) {
    values.push_back(e);
    values.push_back(std::nextafter(e, 2.0f));
    values.push_back(std::nextafter(e, -2.0f));
  }
  testing::InputGenerator gen(0x7a45f3u);
  while (values.size() < 4 * 4096) {
    float u = gen.unit();
    values.push_back(u < 0.1f   ? gen.uniform(-0.1f, 1.1f)
                     : u < 0.3f ? gen.uniform(0.0f, 0.1f)
                                : gen.unit());
  }
  std::vector<vec4> result;
  for (std::size_t i = 0; i + 3 < values.size(); i += 4)
    result.push_back(vec4(values[i], values[i + 1], values[i + 2], values[i + 3]));
  // Every edge value also through the scalar form (.w).
  for (float e : values) {
    if (result.size() >= 4096 + edges.size() * 3) break;
    result.push_back(vec4(0.5f, 0.5f, 0.5f, e));
  }
  return result;
}

// Per-value bound: GLSL 4.50 §4.7.1 for the GPU side plus ≤ 1 ULP per libm call and 0.5 ULP
// per rounding for the C++ side. Linear segments are one correctly rounded × on both sides
// (equal, but for denormals, which GLSL may flush) or one ÷ (GLSL: 2.5 ULP).
using Bound = double (*)(double in, double out);

constexpr double kFlushed = std::numeric_limits<float>::min();
constexpr double kSrgbY = 1.0f / 2.4f, kBtY = 0.45f, kBtAlpha = 1.09929682680944f,
                 kBtBeta = 0.018053968510807f;

// a·pow(x, y) − (a − 1): pow's bound and ≤ 2 roundings per side, relative to a·pow(x, y).
double encodeBound(double x, double y, double a) {
  double scaled = a * std::pow(x, y);
  return scaled * (glslPowRelativeError(x, y) + kUlp + 4.0 * kUlp);
}

// pow((e + a − 1) / a, y): the base carries + and ÷ (GLSL 0.5 + 2.5 ULP, C++ 0.5 + 0.5),
// amplified y-fold by the power.
double decodeBound(double e, double y, double a, double out) {
  double base = (e + a - 1.0) / a;
  return std::abs(out) * (glslPowRelativeError(base, y) + kUlp + y * 4.0 * kUlp);
}

double srgbEncodeBound(double x, double) {
  return x <= 0.0031308f ? kFlushed : encodeBound(x, kSrgbY, 1.055f);
}
double srgbDecodeBound(double e, double out) {
  return e <= 0.04045f ? kFlushed + 3.0 * kUlp * out : decodeBound(e, 2.4f, 1.055f, out);
}
double bt2020EncodeBound(double x, double) {
  return x < kBtBeta ? kFlushed : encodeBound(x, kBtY, kBtAlpha);
}
double bt2020DecodeBound(double e, double out) {
  return e < 4.5f * static_cast<float>(kBtBeta) ? kFlushed + 3.0 * kUlp * out
                                                : decodeBound(e, 1.0f / 0.45f, kBtAlpha, out);
}

void checkTransfer(const std::string& name, float (*scalar)(float), vec3 (*vector)(const vec3&),
                   Bound bound) {
  std::vector<vec4> in = signals();
  Program kernel =
      testing::parityKernel("transfer.comp", {{"TRANSFER", name}, {"TRANSFER3", name + "3"}});
  std::vector<vec4> gpu = testing::runParityKernel<vec4>(kernel, std::span<const vec4>(in));
  ParityReport report(name, {});
  for (std::size_t i = 0; i < in.size(); ++i) {
    vec3 cpu3 = vector(vec3(in[i]));
    float cpu = scalar(in[i].w);
    for (int k = 0; k < 4; ++k) {
      char input[96];
      std::snprintf(input, sizeof input, "%s(%.9g)", name.c_str(), in[i][k]);
      float expected = k < 3 ? cpu3[k] : cpu;
      report.compare(gpu[i][k], expected, input, bound(in[i][k], expected));
    }
  }
  report.finish();
}

// Tolerance (all four): per value, GLSL 4.50's bound for pow (exp2/log2: 3 + 2|y·log2 x| ULP
// and 2^-21 or 3 ULP for log2) plus each side's roundings. Reason: each curve is one pow, scaled
// and offset; the linear segments are exact or one division.
TEST_F(GpuTest, SrgbEncodeMatchesCpu) {
  checkTransfer("srgbEncode", shared::srgbEncode, shared::srgbEncode3, srgbEncodeBound);
}
TEST_F(GpuTest, SrgbDecodeMatchesCpu) {
  checkTransfer("srgbDecode", shared::srgbDecode, shared::srgbDecode3, srgbDecodeBound);
}
TEST_F(GpuTest, Bt2020EncodeMatchesCpu) {
  checkTransfer("bt2020Encode", shared::bt2020Encode, shared::bt2020Encode3, bt2020EncodeBound);
}
TEST_F(GpuTest, Bt2020DecodeMatchesCpu) {
  checkTransfer("bt2020Decode", shared::bt2020Decode, shared::bt2020Decode3, bt2020DecodeBound);
}

}  // namespace
}  // namespace prism::gpu
