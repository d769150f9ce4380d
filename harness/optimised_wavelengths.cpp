#include "harness/optimised_wavelengths.h"

#include <cstdio>
#include <optional>

#include <fmt/format.h>

#include "harness/progress_bar.h"
#include "scene/scene_emission.h"
#include "spectral/colour_space.h"
#include "spectral/observer.h"

namespace prism::harness {

void fitOptimisedWavelengths(const Scene& scene, const render::FrameSettings& settings,
                             const RgbToSpectrumTable& table) {
  const SamplingSettings sampling = render::effectiveSampling(settings);
  if (sampling.strategy != SamplingStrategy::Optimised) return;
  validate(sampling);
  const Observer& obs = observer(settings.observer);
  const WavelengthFitProblem problem = sceneWavelengthFitProblem(sampling, scene, colourSpace(scene.colourSpace), table);
  std::optional<ProgressBar> bar;
  const FittedWavelengths set = cachedFitWavelengths(problem, obs, [&bar](std::size_t done, std::size_t total) {
    if (!bar) bar.emplace("fitting wavelengths");
    bar->update(done, total);
  });
  const FitError error = fitError(set, problem, obs);
  if (error.mean > kVisibleFitError)
    fmt::print(stderr,
               "prism: warning: the {} wavelengths fitted over {:g}–{:g} nm show this scene's surfaces under its lights "
               "{:.1f} ΔE00 from the 1 nm integral over that range on average (worst {:.1f}): more wavelengths\n",
               set.lambdaNm.size(), sampling.minNm, sampling.maxNm, error.mean, error.max);
}

}  // namespace prism::harness
