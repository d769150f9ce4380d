#include "gpu/gpu_test_support.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <limits>
#include <sstream>

#include "gpu/error.h"
#include "core/data_files.h"

namespace prism::gpu::testing {

std::filesystem::path testDirectory() { return PRISM_GPU_TEST_DIR; }

std::filesystem::path loaderPath(std::string_view name) { return testDirectory() / "loader" / name; }

std::size_t lineOf(const std::filesystem::path& file, std::string_view marker) {
  std::ifstream in(file);
  std::size_t number = 0;
  for (std::string line; std::getline(in, line);) {
    ++number;
    if (line.find(marker) != std::string::npos) return number;
  }
  ADD_FAILURE() << marker << " not in " << file;
  return 0;
}

std::filesystem::path kernelPath(std::string_view name) {
  return testDirectory() / "kernels" / name;
}

std::filesystem::path drawShaderPath(std::string_view name) {
  return testDirectory() / "draw" / name;
}

std::vector<std::filesystem::path> sharedIncludeDirs() { return {shaderDirectory() / "shared"}; }

Program parityKernel(std::string_view name, std::vector<ShaderDefine> defines) {
  ProgramDesc desc;
  desc.compute = kernelPath(name);
  desc.includeDirs = sharedIncludeDirs();
  desc.defines = std::move(defines);
  desc.label = std::string(name);
  return Program(desc);
}

Program drawProgram(std::string_view vertex, std::string_view fragment,
                    std::vector<ShaderDefine> defines) {
  ProgramDesc desc;
  desc.vertex = drawShaderPath(vertex);
  desc.fragment = drawShaderPath(fragment);
  desc.defines = std::move(defines);
  desc.label = std::string(vertex) + " + " + std::string(fragment);
  return Program(desc);
}

void GpuTest::SetUp() {
  try {
    mContext = std::make_unique<HeadlessContext>();
  } catch (const GpuError& e) {
    FAIL() << diagnosticName(e.id()) << ": " << e.what();
  }
  mContext->debugOutput().setSink([this](const DebugMessage& m) {
    printDebugMessage(m);
    if (m.id == Diagnostic::GlDebugError) mErrors.push_back(m);
  });
}

void GpuTest::TearDown() {
  if (!mContext) return;
  for (const DebugMessage& m : mErrors) ADD_FAILURE() << "unexpected " << formatDebugMessage(m);
  mContext.reset();
}

std::vector<DebugMessage> GpuTest::takeDebugErrors() { return std::exchange(mErrors, {}); }

std::int64_t ulpDistance(float a, float b) {
  if (!std::isfinite(a) || !std::isfinite(b)) {
    bool same = (std::isnan(a) && std::isnan(b)) || a == b;
    return same ? 0 : std::numeric_limits<std::int64_t>::max();
  }
  // Map the floats onto a line of integers where neighbours differ by one (−0 and +0 coincide).
  auto ordered = [](float f) {
    auto bits = static_cast<std::int64_t>(std::bit_cast<std::uint32_t>(f));
    return bits & 0x80000000 ? -(bits & 0x7fffffff) : bits;
  };
  std::int64_t d = ordered(a) - ordered(b);
  return d < 0 ? -d : d;
}

double glslPowRelativeError(double x, double y) {
  double log2x = std::log2(x);
  double logError = x >= 0.5 && x <= 2.0 ? 0x1p-21 : 3.0 * kUlp * std::abs(log2x);
  double argument = y * log2x;
  double argumentError =
      std::abs(y) * logError + 0.5 * kUlp * std::abs(argument);  // y·log2 x rounds
  return (3.0 + 2.0 * std::abs(argument)) * kUlp + argumentError * std::log(2.0);
}

void ParityReport::compare(float gpu, float cpu, const std::string& input, double extraAbsolute) {
  ++mCount;
  std::int64_t ulps = ulpDistance(gpu, cpu);
  bool nonFinite = !std::isfinite(gpu) || !std::isfinite(cpu);
  double absolute = 0.0, relative = 0.0;
  if (nonFinite) {
    absolute = relative = ulps == 0 ? 0.0 : std::numeric_limits<double>::infinity();
  } else {
    absolute = std::abs(static_cast<double>(gpu) - static_cast<double>(cpu));
    relative = cpu != 0.0f ? absolute / std::abs(static_cast<double>(cpu)) : absolute;
  }
  // The fraction of the tolerance this value uses: the smaller of the two criteria's.
  double allowed = mTolerance.absolute + extraAbsolute + mTolerance.relative * std::abs(cpu);
  double usedAbsolute = absolute == 0.0 ? 0.0
                        : allowed > 0.0 ? absolute / allowed
                                        : std::numeric_limits<double>::infinity();
  double usedUlps = ulps == 0 ? 0.0
                    : mTolerance.ulps > 0
                        ? static_cast<double>(ulps) / static_cast<double>(mTolerance.ulps)
                        : std::numeric_limits<double>::infinity();
  double used = std::min(usedAbsolute, usedUlps);
  // A NaN share (e.g. from a NaN bound) must fail, not slip past every comparison.
  if (std::isnan(used)) used = std::numeric_limits<double>::infinity();
  if (used > mMaxUsed || mWorstInput.empty()) {
    std::ostringstream s;
    s.precision(9);
    s << input << " gpu " << gpu << " cpu " << cpu;
    mWorstInput = s.str();
  }
  mMaxUsed = std::max(mMaxUsed, used);
  mMaxAbsolute = std::max(mMaxAbsolute, absolute);
  mMaxRelative = std::max(mMaxRelative, relative);
  mMaxUlps = std::max(mMaxUlps, ulps);
  if (used > 1.0 && mFailures++ == 0) {
    std::ostringstream s;
    s.precision(9);
    s << input << ": gpu " << gpu << " cpu " << cpu << " (|d| " << absolute << ", allowed "
      << allowed << ", " << ulps << " ULP)";
    mFirstFailure = s.str();
  }
}

void ParityReport::finish() {
  std::printf(
      "parity %-18s N=%-5zu max|d|=%-9.3g max rel=%-9.3g max ULP=%-5lld tolerance used %.2f"
      " (at %s)\n",
      mFunction.c_str(), mCount, mMaxAbsolute, mMaxRelative,
      static_cast<long long>(std::min<std::int64_t>(mMaxUlps, 99999)), mMaxUsed,
      mWorstInput.c_str());
  ::testing::Test::RecordProperty(mFunction + "_max_abs", std::to_string(mMaxAbsolute));
  ::testing::Test::RecordProperty(mFunction + "_tolerance_used", std::to_string(mMaxUsed));
  EXPECT_EQ(mFailures, 0u) << mFunction << ": " << mFailures << " of " << mCount
                           << " values outside tolerance (abs " << mTolerance.absolute << ", rel "
                           << mTolerance.relative << ", " << mTolerance.ulps
                           << " ULP, plus any per-value bound); first: " << mFirstFailure;
  EXPECT_GE(mCount, 1000u) << mFunction << ": a parity test needs at least 1000 values";
}

}  // namespace prism::gpu::testing
