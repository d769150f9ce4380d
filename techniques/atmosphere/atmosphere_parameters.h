// The Earth's atmosphere as Prism models it (shaders/shared/atmosphere_model.glsl): its
// parameters, with Bruneton's demo values as defaults (data/SOURCES.md), the measured spectra
// (extraterrestrial solar irradiance, ozone cross-section; data/atmosphere_spectra.csv) and the
// optical coefficients at a wavelength, in double precision (the reference) or packed for one
// batch of four wavelengths (the real-time tables).
#pragma once

#include <string>

#include <glm/glm.hpp>

#include "spectral/spectrum.h"
#include "techniques/atmosphere/atmosphere_layout.h"

namespace prism::atmosphere {

struct AtmosphereParameters {
  double bottomRadiusKm = 6360.0;  // the ground
  double topRadiusKm = 6420.0;
  double rayleighScaleHeightKm = 8.0;
  double rayleighScatteringPerKm = 1.24062e-3;  // at sea level and 1 µm; ∝ λ⁻⁴
  bool aerosols = true;                         // false: no Mie at all (Rayleigh + ozone)
  double mieScaleHeightKm = 1.2;
  double mieAngstromAlpha = 0.0;   // extinction ∝ λ^−α (λ in µm)
  double mieAngstromBeta = 5.328e-3;  // aerosol optical depth at 1 µm
  double mieSingleScatteringAlbedo = 0.9;
  double miePhaseG = 0.8;               // Cornette–Shanks asymmetry
  double ozoneColumnDu = 300.0;         // total column, Dobson units
  double ozonePeakAltitudeKm = 25.0;    // the tent's top
  double ozoneHalfWidthKm = 15.0;       // density 0 at peak ± this
  double groundAlbedo = 0.1;
  double sunAngularRadiusRad = 0.004675;
  bool multipleScattering = true;

  bool operator==(const AtmosphereParameters&) const = default;
};

// Error naming the parameter when one is out of its physical range ("ozone column (DU) = -1 must
// be within 0..1000"; callers add where it came from).
void validate(const AtmosphereParameters& p);

// The atmosphere's measured spectra (data/atmosphere_spectra.csv, read once; linear between
// its 10 nm samples, zero outside 360–830 nm).
double solarIrradiance(double lambdaNm);      // W·m⁻²·nm⁻¹ at the top of the atmosphere
double ozoneCrossSectionM2(double lambdaNm);  // m² per molecule
const TabulatedSpectrum& solarIrradianceSpectrum();

// Coefficients at one wavelength, 1/km at density 1 (ozone: at its peak).
struct OpticalCoefficients {
  double rayleighScattering = 0.0;
  double mieScattering = 0.0;
  double mieExtinction = 0.0;
  double ozoneAbsorption = 0.0;
  double solarIrradiance = 0.0;
};
OpticalCoefficients opticalCoefficients(const AtmosphereParameters& p, double lambdaNm);

// The GPU's form for one batch. A wavelength ≤ 0 is an unused channel (everything 0);
// solarIrradiance replaces the measured one per channel (an RGB renderer's sun colour).
shared::GpuAtmosphere packAtmosphere(const AtmosphereParameters& p, const glm::vec4& lambdaNm);
shared::GpuAtmosphere packAtmosphere(const AtmosphereParameters& p, const glm::vec4& lambdaNm,
                                     const glm::vec4& solarIrradiance);

}  // namespace prism::atmosphere
