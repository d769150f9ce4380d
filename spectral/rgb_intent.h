// What an RGB colour means decides how it becomes a spectrum: three intents, three types
// (pbrt-v4's RGBAlbedoSpectrum, RGBUnboundedSpectrum and RGBIlluminantSpectrum; Jakob & Hanika
// 2019, "A Low-Dimensional Function Space for Efficient Spectral Upsampling", §5).
//
//   RgbAlbedoSpectrum      a reflectance: the Jakob–Hanika reflectance of the colour, each
//                          channel clamped to [0, 1] first.
//   RgbUnboundedSpectrum   any non-negative colour (emission, values above 1): scale times the
//                          reflectance of rgb / scale, scale = 2·max(r, g, b). The fitted colour's
//                          largest channel is then ½, clear of the unreachable pure white.
//   RgbIlluminantSpectrum  a light's colour: the unbounded spectrum times the colour space's white
//                          illuminant (D65, or D60 for ACES), so (1, 1, 1) is that white, not a
//                          flat spectrum, and the light's chromaticity is the colour's.
//
// Each holds the sigmoid coefficients of one albedo, evaluated by shaders/shared/sigmoid.glsl
// (in float, as the GPU does). The coefficients come from the colour space's table, the lookup
// the GPU makes too, or, for a colour met once with no table at hand (a scene's light colours on
// load), from an exact fit (SigmoidFitter, a few milliseconds).
#pragma once

#include <glm/vec3.hpp>

#include "spectral/colour_space.h"
#include "spectral/rgb_to_spectrum_table.h"
#include "spectral/spectrum.h"

namespace prism {

class RgbAlbedoSpectrum {
 public:
  // NaN reads as 0 (RgbToSpectrumTable::lookup).
  RgbAlbedoSpectrum(const RgbToSpectrumTable& table, const glm::vec3& rgb);

  const glm::vec3& coefficients() const { return mCoeffs; }
  Spectrum toDense() const;

 private:
  glm::vec3 mCoeffs;
};

class RgbUnboundedSpectrum {
 public:
  // Negative, NaN and infinite channels read as 0; black has scale 0. Never NaN or Inf out.
  RgbUnboundedSpectrum(const RgbToSpectrumTable& table, const glm::vec3& rgb);
  // The same rule, the coefficients fitted exactly under the space's white through CIE 1931.
  static RgbUnboundedSpectrum fitted(const RgbColourSpace& space, const glm::vec3& rgb);

  const glm::vec3& coefficients() const { return mCoeffs; }
  float scale() const { return mScale; }
  // scale · reflectance at one wavelength, multiplied in float as a shader would.
  float at(float lambdaNm) const;
  // The same on the 1 nm grid, multiplied in double (exact: two floats' product fits a double).
  Spectrum toDense() const;

 private:
  RgbUnboundedSpectrum(const glm::vec3& coeffs, float scale) : mCoeffs(coeffs), mScale(scale) {}

  glm::vec3 mCoeffs;
  float mScale;
};

// The colour space's white illuminant (D65, or D60 for ACES): what RgbIlluminantSpectrum's
// (1, 1, 1) is, scaled to a luminous integral (observer.h) of `luminance`.
Spectrum scaledWhiteIlluminant(const RgbColourSpace& space, double luminance);

class RgbIlluminantSpectrum {
 public:
  // whiteLuminance: the luminous integral (observer.h) of the colour (1, 1, 1), in cd/m² when
  // the spectrum is radiance in W·sr⁻¹·m⁻²·nm⁻¹; another colour's is about whiteLuminance times
  // its Y (as well as the coefficients reproduce it). `table` must be `space`'s (checked).
  RgbIlluminantSpectrum(const RgbToSpectrumTable& table, const RgbColourSpace& space, const glm::vec3& rgb,
                        double whiteLuminance = 1.0);
  // The coefficients fitted exactly (RgbUnboundedSpectrum::fitted).
  static RgbIlluminantSpectrum fitted(const RgbColourSpace& space, const glm::vec3& rgb,
                                      double whiteLuminance = 1.0);

  // White (piecewise linear between 1 nm nodes) times RgbUnboundedSpectrum::at.
  double at(double lambdaNm) const;
  Spectrum toDense() const;

 private:
  RgbIlluminantSpectrum(const RgbColourSpace& space, const RgbUnboundedSpectrum& unbounded, double whiteLuminance);

  Spectrum mWhite;  // the space's white illuminant, scaled to whiteLuminance
  RgbUnboundedSpectrum mUnbounded;
};

}  // namespace prism
