// The CPU side of a frame's wavelengths: what the lights' pdf costs to build (once per change of
// the lights or settings) and what drawing a frame's set and its integration matrices costs per
// frame, for the rotated grid, the observer's importance and the lights' pdf. The GPU's work is
// the same for every strategy (n wavelengths); this is all a strategy adds.
#include <benchmark/benchmark.h>

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

// One frame's 16 wavelengths and their 3×4 matrices; the argument is the SamplingStrategy.
void wavelengthsPerFrame(benchmark::State& state) {
  const Observer& cie = observer("cie1931");
  const auto strategy = static_cast<SamplingStrategy>(state.range(0));
  WavelengthSampler sampler({16, kLambdaMinNm, kLambdaMaxNm, strategy}, cie, illuminant("F11"));
  std::uint32_t frame = 0;
  for (auto _ : state) {
    std::vector<SampledWavelengths> batches = sampler.sample(frame++);
    benchmark::DoNotOptimize(integrationMatrices(batches, cie));
  }
  state.SetLabel(std::string(samplingStrategyName(strategy)));
}
BENCHMARK(wavelengthsPerFrame)
    ->Arg(static_cast<int>(SamplingStrategy::Rotated))
    ->Arg(static_cast<int>(SamplingStrategy::Importance))
    ->Arg(static_cast<int>(SamplingStrategy::Lights));

}  // namespace
}  // namespace prism
