// Shared by the gpu_test binary: a fixture with a fresh headless context per test whose
// KHR_debug errors fail the test, paths to the test kernels, deterministic inputs, and the
// error statistics every parity test reports.
#pragma once

#include <gtest/gtest.h>

#include <cstdint>
#include <filesystem>
#include <memory>
#include <random>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "gpu/buffer.h"
#include "gpu/compute.h"
#include "gpu/headless_context.h"
#include "gpu/program.h"

namespace prism::gpu::testing {

std::filesystem::path testDirectory();                        // gpu/tests in the source tree
std::filesystem::path kernelPath(std::string_view name);      // gpu/tests/kernels/NAME
std::filesystem::path drawShaderPath(std::string_view name);  // gpu/tests/draw/NAME
std::vector<std::filesystem::path> sharedIncludeDirs();       // {shaderDirectory()/"shared"}
std::filesystem::path loaderPath(std::string_view name);      // gpu/tests/loader/NAME
// 1-based line of the first line of `file` containing `marker` (a test failure when none does).
std::size_t lineOf(const std::filesystem::path& file, std::string_view marker);

// A compute program from gpu/tests/kernels/NAME, #including shaders/shared through the loader.
Program parityKernel(std::string_view name, std::vector<ShaderDefine> defines = {});
// A draw program from gpu/tests/draw/VERTEX and gpu/tests/draw/FRAGMENT.
Program drawProgram(std::string_view vertex, std::string_view fragment,
                    std::vector<ShaderDefine> defines = {});

// A context for every test (each test is its own process under ctest). No context is a
// failure, not a skip: CI has Mesa's llvmpipe. Any GlDebugError message fails the test unless
// the test took it with takeDebugErrors().
class GpuTest : public ::testing::Test {
 protected:
  void SetUp() override;
  void TearDown() override;

  HeadlessContext& context() { return *mContext; }
  std::vector<DebugMessage> takeDebugErrors();

 private:
  std::unique_ptr<HeadlessContext> mContext;
  std::vector<DebugMessage> mErrors;
};

// Runs `kernel` with `a` at SSBO binding 0, `b` at binding 1 (if not empty), the output at
// binding 2 (one Out per element of a) and uniform uCount = a.size().
template <class Out, class A, class B = A>
std::vector<Out> runParityKernel(const Program& kernel, std::span<const A> a,
                                 std::span<const B> b = {}) {
  Buffer inA = Buffer::fromSpan(a, "parity input a");
  inA.bindBase(GL_SHADER_STORAGE_BUFFER, 0);
  Buffer inB;
  if (!b.empty()) {
    inB = Buffer::fromSpan(b, "parity input b");
    inB.bindBase(GL_SHADER_STORAGE_BUFFER, 1);
  }
  Buffer out({a.size() * sizeof(Out), nullptr, GL_DYNAMIC_STORAGE_BIT, "parity output"});
  out.bindBase(GL_SHADER_STORAGE_BUFFER, 2);
  kernel.setUniform("uCount", static_cast<GLuint>(a.size()));
  runCompute1D(kernel, a.size());
  return out.read<Out>();
}

// Deterministic inputs: std::mt19937's sequence is fixed by the standard, and the conversion to
// float is ours (the standard distributions are not portable across libraries).
class InputGenerator {
 public:
  explicit InputGenerator(std::uint32_t seed) : mEngine(seed) {}
  std::uint32_t bits() { return static_cast<std::uint32_t>(mEngine()); }
  float unit() { return static_cast<float>(bits() >> 8) * (1.0f / 16777216.0f); }  // [0, 1)
  float uniform(float lo, float hi) { return lo + (hi - lo) * unit(); }

 private:
  std::mt19937 mEngine;
};

// Distance in units in the last place between two finite floats of any sign (0 and -0 are 0
// apart); INT64_MAX when exactly one is NaN or infinite.
std::int64_t ulpDistance(float a, float b);

// One ULP relative to a float's value is at most 2^-23 (and at least 2^-24).
constexpr double kUlp = 0x1p-23;

// The error of GLSL's pow(x, y), relative to its value, that GLSL 4.50 §4.7.1 allows: pow is
// inherited from exp2(y·log2 x); log2 is within 2^-21 absolute on [0.5, 2] and 3 ULP outside;
// exp2 is within 3 + 2·|argument| ULP; the argument's error scales the result by 2^Δ ≈ 1 + Δ·ln 2.
double glslPowRelativeError(double x, double y);

// How far GPU results are from the CPU's, and the tolerance they are held to:
//   pass if |gpu - cpu| <= absolute + relative·|cpu| (+ a per-value bound), or
//   ulpDistance(gpu, cpu) <= ulps.
// Both NaN, or equal infinities, agree. The statistics are printed (and recorded as gtest
// properties): N, max |Δ|, max relative, max ULP, and the largest fraction of the tolerance used.
struct Tolerance {
  double absolute = 0.0;
  double relative = 0.0;
  std::int64_t ulps = 0;
};

class ParityReport {
 public:
  ParityReport(std::string function, Tolerance tolerance)
      : mFunction(std::move(function)), mTolerance(tolerance) {}
  // Compares one value; `input` describes the arguments for the failure message.
  // `extraAbsolute` widens the absolute tolerance for this value alone, for bounds that depend
  // on the input (e.g. the rounding error of a polynomial, scaled by a derivative).
  void compare(float gpu, float cpu, const std::string& input, double extraAbsolute = 0.0);
  // Expects no failures and at least 1000 values; prints the statistics.
  void finish();

  double maxAbsolute() const { return mMaxAbsolute; }
  double maxToleranceUsed() const { return mMaxUsed; }

 private:
  std::string mFunction;
  Tolerance mTolerance;
  std::size_t mCount = 0, mFailures = 0;
  double mMaxAbsolute = 0.0, mMaxRelative = 0.0, mMaxUsed = 0.0;
  std::int64_t mMaxUlps = 0;
  std::string mWorstInput, mFirstFailure;
};

}  // namespace prism::gpu::testing
