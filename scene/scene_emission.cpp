#include "scene/scene_emission.h"

#include <algorithm>
#include <numbers>
#include <vector>

#include "scene/scene_loader.h"
#include "scene/scene_spectra.h"
#include "spectral/rgb_intent.h"
#include "spectral/wavelength_fit.h"

namespace prism {
namespace {

// The emitting materials some mesh shows (one defined but used by none emits nothing).
std::vector<const Material*> shownEmitters(const Scene& scene) {
  std::vector<const Material*> out;
  for (std::size_t i = 0; i < scene.materials.size(); ++i) {
    const bool shown = std::ranges::any_of(scene.meshes, [&](const Mesh& mesh) {
      return static_cast<std::size_t>(mesh.material) == i;
    });
    const Material& m = scene.materials[i];
    if (shown && (m.emission || m.emitsRgb())) out.push_back(&m);
  }
  return out;
}

// An emitter's spectrum: its own, or glTF's colour upsampled as a light's at `luminance` cd/m²
// for the colour space's white: its factor's, or, under a texture, which may take it to any
// colour within the factor's channels, the white at the factor's largest (followed by the
// factor's hue, the lights' pdf sampled a texture's other colours poorly: 32 frames of 16 left
// the fixture's saturated texels 1 % off in luminance, against 0.02 % for the rotated grid).
Spectrum emitterSpectrum(const Material& m, double luminance, const RgbColourSpace& space,
                         const RgbToSpectrumTable& table) {
  if (m.emission) return m.emission->spd * luminance;
  const glm::vec3 colour = m.emissiveTexture >= 0
                               ? glm::vec3(std::max({m.emissiveFactor.r, m.emissiveFactor.g, m.emissiveFactor.b}))
                               : m.emissiveFactor;
  return RgbIlluminantSpectrum(table, space, colour, luminance).toDense();
}

}  // namespace

Spectrum sceneEmission(const Scene& scene, const RgbColourSpace& space, const RgbToSpectrumTable& table) {
  Spectrum emission;
  for (const Light& light : scene.lights) emission += light.spd * static_cast<double>(light.intensity);
  if (scene.backgroundLuminance > 0.0f) emission += std::numbers::pi * backgroundRadiance(scene, space, table).toDense();
  for (const Material* m : shownEmitters(scene))
    emission += std::numbers::pi *
                emitterSpectrum(*m, m->emission ? m->emission->luminance : m->emissiveLuminance, space, table);
  return emission;
}

WavelengthFitProblem sceneWavelengthFitProblem(const SamplingSettings& settings, const Scene& scene,
                                               const RgbColourSpace& space, const RgbToSpectrumTable& table) {
  WavelengthFitProblem problem;
  problem.count = settings.count;
  problem.minNm = settings.minNm;
  problem.maxNm = settings.maxNm;
  auto addLight = [&](const Spectrum& spd) {
    for (const Spectrum& known : problem.lights)
      if (known == spd) return;
    problem.lights.push_back(spd);
  };
  for (const Light& light : scene.lights) addLight(light.spd);
  if (scene.backgroundLuminance > 0.0f) addLight(std::numbers::pi * backgroundRadiance(scene, space, table).toDense());
  // An emitter seen is its spectrum on a white. Each light is fitted under its own white, so its
  // level does not matter: its normalised SPD, as a light's, so that an edit of its luminance (the
  // viewer's slider) finds the cached fit rather than fitting again.
  // glTF's, whose level follows its factor, normalised as a light's too.
  for (const Material* m : shownEmitters(scene))
    addLight(m->emission ? m->emission->spd : normalisedLightSpectrum(emitterSpectrum(*m, 1.0, space, table)));
  // Nothing the frame's wavelengths would see (a scene lit only by a technique's own pass, or
  // dark): fitted under equal energy, so that the default strategy renders every scene.
  if (problem.lights.empty()) problem.lights.push_back(Spectrum::constant(1.0));
  problem.reflectances = standardTrainingReflectances(table);
  for (const Material& m : scene.materials) {
    if (m.conductor) problem.reflectances.push_back(normalIncidenceReflectance(*m.conductor));
    else if (m.reflectance) problem.reflectances.push_back(*m.reflectance);
    else problem.reflectances.push_back(RgbAlbedoSpectrum(table, m.baseColour).toDense());
  }
  return problem;
}

WavelengthSampler sceneWavelengthSampler(const SamplingSettings& settings, const Observer& importance,
                                         const Scene& scene, const RgbColourSpace& space,
                                         const RgbToSpectrumTable& table, const FitProgress& progress) {
  switch (settings.strategy) {
    case SamplingStrategy::Lights: return WavelengthSampler(settings, importance, sceneEmission(scene, space, table));
    case SamplingStrategy::Optimised:
      validate(settings);
      return WavelengthSampler(
          settings, cachedFitWavelengths(sceneWavelengthFitProblem(settings, scene, space, table), importance, progress));
    default: return WavelengthSampler(settings, importance);
  }
}

}  // namespace prism
