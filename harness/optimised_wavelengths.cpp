#include "harness/optimised_wavelengths.h"

#include <optional>

#include "harness/progress_bar.h"
#include "scene/scene_emission.h"
#include "spectral/colour_space.h"
#include "spectral/observer.h"

namespace prism::harness {

void fitOptimisedWavelengths(const Scene& scene, const render::FrameSettings& settings,
                             const RgbToSpectrumTable& table) {
  const SamplingSettings sampling = render::effectiveSampling(settings);
  if (sampling.strategy != SamplingStrategy::Optimised) return;
  std::optional<ProgressBar> bar;
  sceneWavelengthSampler(sampling, observer(settings.observer), scene, colourSpace(scene.colourSpace), table,
                         [&bar](std::size_t done, std::size_t total) {
                           if (!bar) bar.emplace("fitting wavelengths");
                           bar->update(done, total);
                         });
}

}  // namespace prism::harness
