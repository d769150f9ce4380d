// What a scene emits, as one spectrum: the weight the Lights wavelength strategy follows
// (spectral/sampling.h, spectral/wavelength_pdf.h), for the rasteriser's frames and the reference's
// hero wavelengths alike, so that both sample the same pdf.
//
//   E(λ) = Σ_lights intensity·SPD(λ) + π·L_background(λ) + Σ_emitting materials π·L_e(λ)
//
// Each light's SPD is normalised photometrically (scene.h), so intensity·SPD is the spectral
// illuminance it gives a surface facing it (directional: lux) or at 1 m (point, spot: candela):
// lights are weighed without their distance, which the scene does not fix per pixel. π·L is the
// illuminance a uniform surround of radiance L gives, and an emitting material is weighed as one
// (a material no mesh shows emits nothing). A technique's own light is a scene light
// (the sky's sun, at the top of the atmosphere); what a technique scatters (the sky's blue) has
// no spectrum of its own here — the pdf's defensive share covers it.
#pragma once

#include "scene/scene.h"
#include "spectral/colour_space.h"
#include "spectral/observer.h"
#include "spectral/rgb_to_spectrum_table.h"
#include "spectral/sampling.h"

namespace prism {

// `space` is the scene's colour space and `table` its Jakob–Hanika table (the background's colour).
Spectrum sceneEmission(const Scene& scene, const RgbColourSpace& space, const RgbToSpectrumTable& table);

// What the Optimised strategy fits for this scene (spectral/wavelength_fit.h): its lights, each
// alone (distinct spectra once), the background's π·L and each emitting material's spectrum
// (normalised: its luminance changes no fit), as a light seen on the training reflectances (equal
// energy when it has none of them);
// the standard training reflectances
// plus the scene's own (materials' upsampled base colours, measured reflectances, conductors at
// normal incidence); the settings' count and range.
WavelengthFitProblem sceneWavelengthFitProblem(const SamplingSettings& settings, const Scene& scene,
                                               const RgbColourSpace& space, const RgbToSpectrumTable& table);

// The sampler of `settings` for this scene: Lights follows sceneEmission, Optimised fits
// sceneWavelengthFitProblem for `importance` (cached: cachedFitWavelengths; `progress` is called
// only while fitting); the other strategies need neither (and they are not computed for them).
WavelengthSampler sceneWavelengthSampler(const SamplingSettings& settings, const Observer& importance,
                                         const Scene& scene, const RgbColourSpace& space,
                                         const RgbToSpectrumTable& table, const FitProgress& progress = {});

}  // namespace prism
