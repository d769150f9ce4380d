// Spectra a scene gives as RGB, turned into spectra the same way for every renderer.
#pragma once

#include "scene/scene.h"
#include "spectral/rgb_to_spectrum_table.h"

namespace prism {

// The background: an unbounded RGB light colour of Scene::backgroundLuminance cd/m² (for
// white). Spectrally it is the colour space's white illuminant (D65, or D60 for ACES) times the
// unbounded upsampling of the colour (rgb_to_spectrum_table.h), the white normalised so that
// 683 lm/W · ∫ white·ȳ = 1: a white background is that illuminant, not a flat spectrum.
class BackgroundRadiance {
 public:
  // `table` is the scene colour space's Jakob–Hanika table; it is read here only.
  BackgroundRadiance(const Scene& scene, const RgbToSpectrumTable& table);
  // Spectral radiance in W·sr⁻¹·m⁻²·nm⁻¹.
  double at(double lambdaNm) const;

 private:
  Spectrum mWhite;  // normalised white × luminance
  UnboundedUpsampling mUpsampling;
};

}  // namespace prism
