// Spectra a scene gives as RGB, turned into spectra the same way for every renderer.
#pragma once

#include "scene/scene.h"
#include "spectral/colour_space.h"
#include "spectral/rgb_intent.h"
#include "spectral/rgb_to_spectrum_table.h"

namespace prism {

// The background's spectral radiance in W·sr⁻¹·m⁻²·nm⁻¹: its colour as a light colour
// (RgbIlluminantSpectrum), so a white background is the colour space's white illuminant (D65, or
// D60 for ACES) of Scene::backgroundLuminance cd/m², not a flat spectrum. `space` is the scene's
// colour space and `table` its Jakob–Hanika table.
RgbIlluminantSpectrum backgroundRadiance(const Scene& scene, const RgbColourSpace& space,
                                         const RgbToSpectrumTable& table);

// A conductor's reflectance at normal incidence, by the spectral path's own Fresnel formula
// (shaders/shared/brdf.glsl): what RGB mode shows of it, and what a wavelength fit trains on.
Spectrum normalIncidenceReflectance(const ConductorIor& ior);

}  // namespace prism
