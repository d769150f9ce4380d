#include "scene/scene_emission.h"

#include <numbers>

#include "scene/scene_spectra.h"

namespace prism {

Spectrum sceneEmission(const Scene& scene, const RgbColourSpace& space, const RgbToSpectrumTable& table) {
  Spectrum emission;
  for (const Light& light : scene.lights) emission += light.spd * static_cast<double>(light.intensity);
  if (scene.backgroundLuminance > 0.0f) emission += std::numbers::pi * backgroundRadiance(scene, space, table).toDense();
  return emission;
}

WavelengthSampler sceneWavelengthSampler(const SamplingSettings& settings, const Observer& importance,
                                         const Scene& scene, const RgbColourSpace& space,
                                         const RgbToSpectrumTable& table) {
  if (settings.strategy != SamplingStrategy::Lights) return WavelengthSampler(settings, importance);
  return WavelengthSampler(settings, importance, sceneEmission(scene, space, table));
}

}  // namespace prism
