// Spectrum → XYZ: the per-pixel integration every spectral pass ends with, at n sampled
// wavelengths (batches of four, precomputed integration matrices with the illuminant folded in,
// as the GPU pass does) against the dense 1 nm integral used by the references.
#include <benchmark/benchmark.h>

#include <glm/glm.hpp>

#include "shared_cpp.h"
#include "spectral/illuminant.h"
#include "spectral/observer.h"
#include "spectral/sampling.h"

namespace prism::shared {
#include "sigmoid.glsl"
}

namespace prism {
namespace {

// A saturated orange reflectance in the sigmoid model.
const glm::vec3 kCoeffs(-2.0e-4f, 0.26f, -75.0f);

void spectrumToXyzSampled(benchmark::State& state) {
  const Observer& cie = observer("cie1931");
  Spectrum d65 = illuminant("D65");
  SamplingSettings settings{static_cast<int>(state.range(0)), kLambdaMinNm, kLambdaMaxNm,
                            SamplingStrategy::Uniform};
  std::vector<SampledWavelengths> batches = sampleWavelengths(settings, 0, cie);
  std::vector<IntegrationMatrix> matrices = integrationMatrices(batches, cie);
  // Per frame: λ as vec4 and M·diag(illuminant) as a 4-column, 3-row matrix.
  std::vector<glm::vec4> lambdas;
  std::vector<glm::mat4x3> m;
  for (std::size_t b = 0; b < batches.size(); ++b) {
    glm::mat4x3 mb(0.0f);
    glm::vec4 l;
    for (int j = 0; j < 4; ++j) {
      l[j] = static_cast<float>(batches[b].lambdaNm[static_cast<std::size_t>(j)]);
      for (int c = 0; c < 3; ++c)
        mb[j][c] = static_cast<float>(matrices[b](c, j) * d65.at(batches[b].lambdaNm[static_cast<std::size_t>(j)]));
    }
    lambdas.push_back(l);
    m.push_back(mb);
  }
  for (auto _ : state) {
    glm::vec3 xyz(0.0f);
    for (std::size_t b = 0; b < lambdas.size(); ++b)
      xyz += m[b] * shared::sigmoidSpectrum4(kCoeffs, lambdas[b]);
    benchmark::DoNotOptimize(xyz);
  }
  state.SetItemsProcessed(state.iterations());
  state.SetLabel("pixels");
}
BENCHMARK(spectrumToXyzSampled)->Arg(4)->Arg(16)->Arg(64)->Arg(400);

void spectrumToXyzDense1nm(benchmark::State& state) {
  const Observer& cie = observer("cie1931");
  Spectrum d65 = illuminant("D65");
  for (auto _ : state) {
    Spectrum reflectance = sigmoidSpectrum(kCoeffs);
    benchmark::DoNotOptimize(cie.integrate(reflectance * d65));
  }
  state.SetItemsProcessed(state.iterations());
  state.SetLabel("pixels");
}
BENCHMARK(spectrumToXyzDense1nm);

}  // namespace
}  // namespace prism
