// Fits four wavelengths to a tiny sky (one sun elevation, four directions, a 10 nm reference) with
// the installed optimiser, and checks the installed optimised set against the same sky: prints
// whether both reproduce it within mean ΔE00 1.
#include <cstdio>

#include "techniques/atmosphere/sky_evaluation.h"
#include "techniques/atmosphere/wavelength_optimiser.h"

int main() {
  using namespace prism::atmosphere;
  AtmosphereParameters p;
  SkySamples samples = makeSkySamples({10.0}, 2, 2);
  SpectralSky reference = spectralSky(p, 10.0, samples);
  OptimiserSettings settings;
  settings.gridStepNm = 60.0;
  settings.seeds = 1;
  settings.maxEvaluations8 = 300;
  settings.maxEvaluations12 = 300;
  OptimiserResult fit = optimiseWavelengths(samples, reference, settings);
  double fitted = compareSkies(samples, skyTristimulus(p, optimisedStrategy(fit.set, false), samples), reference.xyz)[0].meanDeltaE;
  double shipped = compareSkies(samples, skyTristimulus(p, optimisedStrategy(loadOptimisedWavelengths("aerosols"), false), samples),
                                reference.xyz)[0].meanDeltaE;
  std::printf("fitted %s, shipped %s\n", fitted < 1.0 ? "within 1" : "off", shipped < 1.0 ? "within 1" : "off");
  return 0;
}
