#include "harness/wavelength_report.h"

#include <algorithm>

#include <fmt/format.h>

#include "harness/optimised_wavelengths.h"
#include "scene/scene_emission.h"
#include "spectral/colour_checker.h"
#include "spectral/colour_difference.h"
#include "spectral/colour_space.h"
#include "spectral/observer.h"
#include "spectral/rgb_to_spectrum_cache.h"

namespace prism::harness {
namespace {

constexpr int kMovingStrategyFrames = 32;  // a moving strategy's single frames, each alone, averaged

// The sampler's frames of `light` against the 1 nm integral of `banded`, the light within the
// sampling range (lightWithinRange), in CIELAB against banded's white.
FitError errors(const WavelengthSampler& sampler, int frames, const Spectrum& light, const Spectrum& banded,
                const std::vector<Spectrum>& reflectances, const Observer& obs) {
  const Eigen::Vector3d white = fitWhite(banded, obs);
  FitError e;
  for (const Spectrum& r : reflectances) {
    const Spectrum radiance = light * r;
    const Eigen::Vector3d truth = xyzToLab(obs.integrate(banded * r), white);
    double sum = 0.0;
    for (int f = 0; f < frames; ++f)
      sum += deltaE(xyzToLab(sampler.estimate(static_cast<std::uint32_t>(f), radiance, obs), white), truth,
                    DeltaEFormula::Ciede2000);
    e.mean += sum / frames;
    e.max = std::max(e.max, sum / frames);
  }
  e.mean /= static_cast<double>(reflectances.size());
  return e;
}

}  // namespace

WavelengthReport wavelengthReport(const Scene& scene, const render::FrameSettings& settings,
                                  const RgbToSpectrumTable& table) {
  SamplingSettings sampling = settings.sampling;
  sampling.strategy = SamplingStrategy::Optimised;
  validate(sampling);
  const Observer& obs = observer(settings.observer);
  const RgbColourSpace& space = colourSpace(scene.colourSpace);
  const WavelengthFitProblem problem = sceneWavelengthFitProblem(sampling, scene, space, table);

  WavelengthReport report;
  report.cacheFile = cacheDirectory() / "wavelengths" / (std::to_string(fitKey(problem, obs)) + ".txt");
  report.reflectances = problem.reflectances.size();
  render::FrameSettings optimisedSettings = settings;
  optimisedSettings.sampling = sampling;
  fitOptimisedWavelengths(scene, optimisedSettings, table);  // with a progress bar, into the cache
  const WavelengthSampler optimised = sceneWavelengthSampler(sampling, obs, scene, space, table);
  report.set = *optimised.fitted();

  const std::vector<Spectrum> chart = colourCheckerReflectances();
  const SamplingSettings uniform{sampling.count, sampling.minNm, sampling.maxNm, SamplingStrategy::Uniform};
  const SamplingSettings lights{sampling.count, sampling.minNm, sampling.maxNm, SamplingStrategy::Lights};
  const WavelengthSampler uniformSampler(uniform, obs);
  const WavelengthSampler lightsSampler(lights, obs, sceneEmission(scene, space, table));
  for (const Spectrum& light : problem.lights) {
    LightErrors l;
    // Not a scene light: the background's, or the equal energy fitted when nothing lights the scene.
    l.light = scene.backgroundLuminance > 0.0f ? "background" : "equal energy (no light or background)";
    for (const Light& sceneLight : scene.lights)
      if (sceneLight.spd == light) {
        l.light = sceneLight.spdLabel;
        break;
      }
    // Against the integral over the range, which every strategy's frames estimate.
    const Spectrum banded = lightWithinRange(light, sampling.minNm, sampling.maxNm);
    auto add = [&](std::string name, const WavelengthSampler& sampler, int frames) {
      l.strategies.push_back({std::move(name), errors(sampler, frames, light, banded, chart, obs),
                              errors(sampler, frames, light, banded, problem.reflectances, obs)});
    };
    add("optimised", optimised, 1);
    add("uniform", uniformSampler, 1);
    add(fmt::format("lights (mean of {} single frames)", kMovingStrategyFrames), lightsSampler, kMovingStrategyFrames);
    report.lights.push_back(std::move(l));
  }
  return report;
}

}  // namespace prism::harness
