// Spectral PRT's run-time sums (shaders/shared/prt.glsl) per vertex on the CPU: Ê_j = Σ_k L̃_jk T̃_k
// for j < m, then XYZ = Σ_j Ê_j R̂_j. m = 3 is RGB-PRT's cost, m = 8 the paper's default, 16 the
// most Prism allows. The GPU frame (the 1.5× bound) is not this; this is the CPU twin's.
#include <benchmark/benchmark.h>

#include <random>
#include <vector>

#include "shared_cpp.h"

namespace prism::shared {
#include "spherical_harmonics.glsl"
#include "prt.glsl"
}

namespace prism {
namespace {

void prtVertexShading(benchmark::State& state) {
  const int m = static_cast<int>(state.range(0));
  std::mt19937 rng(14);
  std::uniform_real_distribution<float> u(-1.0f, 1.0f);
  shared::PrtEnvironment environment;
  shared::PrtReflectance reflectance;
  for (int j = 0; j < shared::kPrtMaxBasis; ++j) {
    for (int k = 0; k < shared::kShCoefficients; ++k) environment.basis[j].c[k] = u(rng);
    reflectance.r[j] = glm::vec3(u(rng), u(rng), u(rng));
  }
  std::vector<shared::Sh25> transfer(1024);
  for (shared::Sh25& t : transfer)
    for (float& c : t.c) c = u(rng);
  std::size_t v = 0;
  for (auto _ : state) {
    shared::PrtBasisIrradiance e = shared::prtVertexIrradiance(environment, transfer[v++ & 1023u], m);
    glm::vec3 xyz = shared::prtXyz(e, reflectance, m);
    benchmark::DoNotOptimize(xyz);
  }
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(prtVertexShading)->Arg(3)->Arg(8)->Arg(16);

}  // namespace
}  // namespace prism
