// The CPU side of a frame's wavelengths: what the lights' pdf costs to build and what fitting an
// optimised set costs (each once per change of the lights or settings; the fit is cached on disk
// besides), and what drawing a frame's set and its integration matrices costs per frame, for the
// rotated grid, the observer's importance, the lights' pdf and the optimised set. The GPU's work
// is the same for every strategy (n wavelengths); this is all a strategy adds.
#include <benchmark/benchmark.h>

#include "spectral/colour_checker.h"
#include "spectral/illuminant.h"
#include "spectral/observer.h"
#include "spectral/sampling.h"

namespace prism {
namespace {

void lightsPdfBuild(benchmark::State& state) {
  const Observer& cie = observer("cie1931");
  Spectrum f11 = illuminant("F11");
  for (auto _ : state) {
    WavelengthSampler sampler({16, kLambdaMinNm, kLambdaMaxNm, SamplingStrategy::Lights}, cie, f11);
    benchmark::DoNotOptimize(sampler);
  }
}
BENCHMARK(lightsPdfBuild);

// 16 wavelengths fitted under F11 on the ColorChecker (the renderer's training set adds a few
// hundred gamut reflectances, which scale the fit's cost in proportion).
WavelengthFitProblem f11Problem() {
  return {{illuminant("F11")}, colourCheckerReflectances(), 16};
}

void optimisedSetFit(benchmark::State& state) {
  const Observer& cie = observer("cie1931");
  const WavelengthFitProblem problem = f11Problem();
  for (auto _ : state) benchmark::DoNotOptimize(fitWavelengths(problem, cie));
}
BENCHMARK(optimisedSetFit)->Unit(benchmark::kMillisecond);

// One frame's 16 wavelengths and their 3×4 matrices; the argument is the SamplingStrategy.
void wavelengthsPerFrame(benchmark::State& state) {
  const Observer& cie = observer("cie1931");
  const auto strategy = static_cast<SamplingStrategy>(state.range(0));
  const WavelengthSampler sampler =
      strategy == SamplingStrategy::Optimised
          ? WavelengthSampler({16, kLambdaMinNm, kLambdaMaxNm, strategy}, fitWavelengths(f11Problem(), cie))
          : WavelengthSampler({16, kLambdaMinNm, kLambdaMaxNm, strategy}, cie, illuminant("F11"));
  std::uint32_t frame = 0;
  for (auto _ : state) {
    std::vector<SampledWavelengths> batches = sampler.sample(frame++);
    benchmark::DoNotOptimize(sampler.matrices(batches, cie));
  }
  state.SetLabel(std::string(samplingStrategyName(strategy)));
}
BENCHMARK(wavelengthsPerFrame)
    ->Arg(static_cast<int>(SamplingStrategy::Rotated))
    ->Arg(static_cast<int>(SamplingStrategy::Importance))
    ->Arg(static_cast<int>(SamplingStrategy::Lights))
    ->Arg(static_cast<int>(SamplingStrategy::Optimised));

}  // namespace
}  // namespace prism
