#include "techniques/atmosphere/atmosphere_parameters.h"

#include <cmath>
#include <vector>

#include <fmt/format.h>

#include "core/csv.h"
#include "core/data_files.h"
#include "core/error.h"

namespace prism::atmosphere {
namespace {

constexpr double kDobsonUnitPerM2 = 2.687e20;  // molecules per m² of one Dobson unit

struct Spectra {
  TabulatedSpectrum solar;
  TabulatedSpectrum ozone;
};

const Spectra& spectra() {
  static const Spectra s = [] {
    CsvTable csv = CsvTable::read(dataFile("atmosphere_spectra.csv"));
    int lambdaColumn = csv.column("wavelength_nm");
    int solarColumn = csv.column("solar_irradiance_W_m2_nm");
    int ozoneColumn = csv.column("ozone_cross_section_m2");
    std::vector<double> lambdas, solar, ozone;
    for (const CsvRow& row : csv.rows()) {
      lambdas.push_back(csv.number(row, lambdaColumn));
      solar.push_back(csv.number(row, solarColumn));
      ozone.push_back(csv.number(row, ozoneColumn));
      if (solar.back() < 0.0 || ozone.back() < 0.0) {
        throw Error(fmt::format("{}:{}: negative irradiance or cross-section", csv.path(), row.line));
      }
    }
    return Spectra{TabulatedSpectrum(lambdas, solar, Extrapolation::Zero),
                   TabulatedSpectrum(lambdas, ozone, Extrapolation::Zero)};
  }();
  return s;
}

void require(bool ok, const char* name, double value, const char* range) {
  if (!ok) throw Error(fmt::format("{} = {} must be {}", name, value, range));
}

}  // namespace

void validate(const AtmosphereParameters& p) {
  require(p.bottomRadiusKm >= 1.0 && p.bottomRadiusKm <= 1e5, "planet radius (km)", p.bottomRadiusKm,
          "within 1..100000");
  double height = p.topRadiusKm - p.bottomRadiusKm;
  require(height >= 1.0 && height <= 1000.0, "atmosphere height (km)", height, "within 1..1000");
  require(p.rayleighScaleHeightKm > 0.01 && p.rayleighScaleHeightKm <= height,
          "Rayleigh scale height (km)", p.rayleighScaleHeightKm, "within 0.01 and the atmosphere height");
  require(p.mieScaleHeightKm > 0.01 && p.mieScaleHeightKm <= height, "Mie scale height (km)",
          p.mieScaleHeightKm, "within 0.01 and the atmosphere height");
  require(p.rayleighScatteringPerKm >= 0.0 && p.rayleighScatteringPerKm < 1.0,
          "Rayleigh scattering at 1 µm (1/km)", p.rayleighScatteringPerKm, "within 0..1");
  require(p.mieAngstromBeta >= 0.0 && p.mieAngstromBeta <= 5.0, "Ångström beta", p.mieAngstromBeta,
          "within 0..5");
  require(std::abs(p.mieAngstromAlpha) <= 4.0, "Ångström alpha", p.mieAngstromAlpha, "within -4..4");
  require(p.mieSingleScatteringAlbedo >= 0.0 && p.mieSingleScatteringAlbedo <= 1.0,
          "Mie single-scattering albedo", p.mieSingleScatteringAlbedo, "within 0..1");
  require(p.miePhaseG > -1.0 && p.miePhaseG < 1.0, "Mie g", p.miePhaseG, "within (-1, 1)");
  require(p.ozoneColumnDu >= 0.0 && p.ozoneColumnDu <= 1000.0, "ozone column (DU)", p.ozoneColumnDu,
          "within 0..1000");
  require(p.ozoneHalfWidthKm > 0.1 && p.ozoneHalfWidthKm <= height, "ozone half-width (km)",
          p.ozoneHalfWidthKm, "within 0.1 and the atmosphere height");
  require(p.ozonePeakAltitudeKm >= 0.0 && p.ozonePeakAltitudeKm <= height, "ozone peak altitude (km)",
          p.ozonePeakAltitudeKm, "within 0 and the atmosphere height");
  require(p.groundAlbedo >= 0.0 && p.groundAlbedo <= 1.0, "ground albedo", p.groundAlbedo, "within 0..1");
  require(p.sunAngularRadiusRad > 0.0 && p.sunAngularRadiusRad < 0.1, "sun angular radius (rad)",
          p.sunAngularRadiusRad, "within (0, 0.1)");
}

double solarIrradiance(double lambdaNm) { return spectra().solar.at(lambdaNm); }
double ozoneCrossSectionM2(double lambdaNm) { return spectra().ozone.at(lambdaNm); }
const TabulatedSpectrum& solarIrradianceSpectrum() { return spectra().solar; }

OpticalCoefficients opticalCoefficients(const AtmosphereParameters& p, double lambdaNm) {
  OpticalCoefficients c;
  if (lambdaNm <= 0.0) return c;
  double um = lambdaNm * 1e-3;
  c.rayleighScattering = p.rayleighScatteringPerKm / (um * um * um * um);
  if (p.aerosols) {
    c.mieExtinction = p.mieAngstromBeta / p.mieScaleHeightKm * std::pow(um, -p.mieAngstromAlpha);
    c.mieScattering = c.mieExtinction * p.mieSingleScatteringAlbedo;
  }
  // Peak number density (per m³) so that the tent's column (its half-width) holds the column.
  double peakPerM3 = p.ozoneColumnDu * kDobsonUnitPerM2 / (p.ozoneHalfWidthKm * 1e3);
  c.ozoneAbsorption = peakPerM3 * ozoneCrossSectionM2(lambdaNm) * 1e3;
  c.solarIrradiance = solarIrradiance(lambdaNm);
  return c;
}

shared::GpuAtmosphere packAtmosphere(const AtmosphereParameters& p, const glm::vec4& lambdaNm,
                                     const glm::vec4& solar) {
  shared::GpuAtmosphere a{};
  a.shape = glm::vec4(p.bottomRadiusKm, p.topRadiusKm, p.rayleighScaleHeightKm, p.mieScaleHeightKm);
  a.ozoneMie = glm::vec4(p.ozonePeakAltitudeKm, p.ozoneHalfWidthKm, p.miePhaseG, p.groundAlbedo);
  for (int j = 0; j < 4; ++j) {
    OpticalCoefficients c = opticalCoefficients(p, lambdaNm[j]);
    a.rayleighScattering[j] = static_cast<float>(c.rayleighScattering);
    a.mieScattering[j] = static_cast<float>(c.mieScattering);
    a.mieExtinction[j] = static_cast<float>(c.mieExtinction);
    a.ozoneAbsorption[j] = static_cast<float>(c.ozoneAbsorption);
  }
  a.solarIrradiance = solar;
  a.options = glm::vec4(p.multipleScattering ? 1.0f : 0.0f, static_cast<float>(p.sunAngularRadiusRad),
                        0.0f, 0.0f);
  return a;
}

shared::GpuAtmosphere packAtmosphere(const AtmosphereParameters& p, const glm::vec4& lambdaNm) {
  glm::vec4 solar;
  for (int j = 0; j < 4; ++j) solar[j] = static_cast<float>(opticalCoefficients(p, lambdaNm[j]).solarIrradiance);
  return packAtmosphere(p, lambdaNm, solar);
}

}  // namespace prism::atmosphere
