// Spectral nebulae (Barrès 2023): the CPU marcher's frame time per method and star count, one
// thread, 64×64 pixels, 100 steps along each ray (the paper's setting) through a 32³ fBm cloud,
// Hubble palette. The double-integration baseline samples 7 wavelengths per channel at every step
// (21 in all: the paper's 20 per step, rounded to whole channels); projection uses 4 basis
// elements; light–density 8 elements of the 2D basis; pre-integration one table lookup per star.
// Precomputation (optical depth to each star,
// the bases, the per-voxel light) is outside the timed loop.
//   prism bench --benchmark_filter=Nebula
#include <benchmark/benchmark.h>

#include <map>
#include <memory>

#include "techniques/nebula/nebula_render.h"
#include "techniques/nebula/nebula_scene.h"

namespace prism {
namespace {

const nebula::NebulaRenderer& renderer(int stars) {
  static std::map<int, std::unique_ptr<nebula::NebulaRenderer>> cache;
  auto& r = cache[stars];
  if (!r) {
    nebula::RenderSettings s;
    s.threads = 1;
    r = std::make_unique<nebula::NebulaRenderer>(nebula::benchNebulaModel(stars), s);
  }
  return *r;
}

void nebulaFrame(benchmark::State& state) {
  auto method = static_cast<nebula::Method>(state.range(0));
  int stars = static_cast<int>(state.range(1));
  const nebula::NebulaRenderer& r = renderer(stars);
  nebula::RenderSettings s;
  s.method = method;
  s.steps = 100;
  s.threads = 1;
  s.emissionLines = false;
  if (method == nebula::Method::Reference) s.uniformSamples = 7;
  r.render(s);  // builds what the method builds at its first frame (pre-integration's tables)
  for (auto _ : state) benchmark::DoNotOptimize(r.render(s).pixels.data());
  state.SetLabel(nebula::methodName(method));
}

void nebulaArgs(benchmark::internal::Benchmark* b) {
  for (int stars : {1, 6, 32}) {
    b->Args({static_cast<int>(nebula::Method::Reference), stars});
    b->Args({static_cast<int>(nebula::Method::Projection), stars});
    b->Args({static_cast<int>(nebula::Method::LightDensity), stars});
    b->Args({static_cast<int>(nebula::Method::PreIntegration), stars});
  }
  b->Args({static_cast<int>(nebula::Method::Analytic), 1});
  b->ArgNames({"method", "stars"})->Unit(benchmark::kMillisecond)->UseRealTime();
}
BENCHMARK(nebulaFrame)->Apply(nebulaArgs);

}  // namespace
}  // namespace prism
