// RGB → spectrum on the CPU: building a table, and the two run-time lookup paths.
#include <benchmark/benchmark.h>

#include <random>
#include <vector>

#include "spectral/rgb_to_spectrum_cache.h"
#include "spectral/rgb_to_spectrum_optimiser.h"

namespace prism {
namespace {

std::vector<glm::vec3> randomAlbedos() {
  std::mt19937 rng(3);
  std::uniform_real_distribution<float> unit(0.0f, 1.0f);
  std::vector<glm::vec3> rgbs(4096);
  for (glm::vec3& c : rgbs) c = glm::vec3(unit(rng), unit(rng), unit(rng));
  return rgbs;
}

template <bool kFiltered>
void lookup(benchmark::State& state) {
  const RgbToSpectrumTable& t = rendererRgbToSpectrumTable("srgb");
  std::vector<glm::vec3> rgbs = randomAlbedos();
  std::size_t i = 0;
  for (auto _ : state) {
    const glm::vec3& c = rgbs[i++ & 4095];
    benchmark::DoNotOptimize(kFiltered ? t.lookupFiltered(c) : t.lookup(c));
  }
  state.SetItemsProcessed(state.iterations());
}
void upsamplingLookupManual(benchmark::State& state) { lookup<false>(state); }
void upsamplingLookupFiltered(benchmark::State& state) { lookup<true>(state); }
BENCHMARK(upsamplingLookupManual);
BENCHMARK(upsamplingLookupFiltered);

// The whole optimisation, all hardware threads (2 on the team's machines).
void upsamplingTableBuild(benchmark::State& state) {
  for (auto _ : state)
    benchmark::DoNotOptimize(buildRgbToSpectrumTable({"srgb", static_cast<int>(state.range(0)), 0, {}}));
}
BENCHMARK(upsamplingTableBuild)->Arg(kRendererTableResolution)->Iterations(1)->Unit(benchmark::kSecond)->UseRealTime();

}  // namespace
}  // namespace prism
