#include "techniques/atmosphere/atmosphere_section.h"

#include <algorithm>
#include <cmath>
#include <utility>

#include <fmt/format.h>

#include "core/error.h"
#include "spectral/sampling.h"
#include "techniques/atmosphere/sky_strategy.h"

namespace prism::atmosphere {

glm::vec3 AtmosphereSky::sunDirection() const {
  float e = glm::radians(sunElevationDeg), a = glm::radians(sunAzimuthDeg);
  return glm::vec3(std::cos(e) * std::sin(a), std::sin(e), -std::cos(e) * std::cos(a));
}

std::optional<TechniqueLight> AtmosphereSection::light() const {
  TechniqueLight sun;
  sun.direction = -sunDirection();
  sun.spd = solarIrradianceSpectrum().toDense();
  sun.spdLabel = "sun (top of the atmosphere)";
  sun.castsShadows = true;
  return sun;
}

TechniqueBlock AtmosphereSection::pack(const FramePackInput& input) const {
  if (input.ownLight < 0) throw Error("the atmosphere has no sun light (the scene loader adds it)");
  TechniqueBlock block;
  block.key = kKey;
  shared::SkyConstants constants{};
  constants.originKm = static_cast<float>(originKm());
  constants.sunLight = input.ownLight;
  block.constantsBinding = shared::kSkyConstantsBinding;
  block.setConstants(constants);
  block.dataBinding = shared::kSkyAtmospheresBinding;
  const int batchCount = static_cast<int>(input.batches.size());
  for (int b = 0; b < batchCount; ++b) {
    glm::vec4 solar =
        input.lightSpectra[static_cast<std::size_t>(shared::lightSpectrumIndex(input.ownLight, b, batchCount))] *
        input.ownLightIntensity;
    glm::vec4 lambdaNm = input.batches[static_cast<std::size_t>(b)].lambdaNm;
    if (input.rgbMode) {
      solar.w = 0.0f;
      lambdaNm = rgbStandInWavelengths(0.0f);  // no fourth channel: the sky's coefficients there are 0
    }
    block.appendData(packAtmosphere(parameters, lambdaNm, solar));
  }
  return block;
}

void readAtmosphereKeys(const schema::Node& n, AtmosphereSky& a, std::vector<std::string_view> extraKeys) {
  using schema::Range;
  std::vector<std::string_view> keys{"sun", "ground_altitude", "planet_radius", "atmosphere_height",
                                     "rayleigh_scale_height", "aerosols", "turbidity", "angstrom_alpha",
                                     "mie_scale_height", "mie_albedo", "mie_g", "ozone", "ground_albedo",
                                     "multiple_scattering"};
  keys.insert(keys.end(), extraKeys.begin(), extraKeys.end());
  n.expectObject(keys);
  AtmosphereParameters& p = a.parameters;
  if (auto sun = n.optionalChild("sun")) {
    sun->expectObject({"elevation", "azimuth"});
    a.sunElevationDeg = sun->numberF("elevation", a.sunElevationDeg,
                                     Range::closed(-a.kSunElevationLimitDeg, a.kSunElevationLimitDeg));
    a.sunAzimuthDeg = sun->numberF("azimuth", a.sunAzimuthDeg, Range::closed(-a.kSunAzimuthLimitDeg, a.kSunAzimuthLimitDeg));
  }
  a.groundAltitudeM = n.numberF("ground_altitude", 0.0f, Range::closed(0.0, 50000.0));
  const double heightKm = p.topRadiusKm - p.bottomRadiusKm;  // kept when only the radius is given
  p.bottomRadiusKm = n.number("planet_radius", p.bottomRadiusKm, Range::closed(1.0, 1e5));
  p.topRadiusKm = p.bottomRadiusKm + n.number("atmosphere_height", heightKm, Range::closed(1.0, 1000.0));
  p.rayleighScaleHeightKm = n.number("rayleigh_scale_height", p.rayleighScaleHeightKm, Range::above(0.01));
  p.aerosols = n.boolean("aerosols", p.aerosols);
  p.mieAngstromBeta = n.number("turbidity", p.mieAngstromBeta, Range::closed(0.0, 5.0));
  p.mieAngstromAlpha = n.number("angstrom_alpha", p.mieAngstromAlpha, Range::closed(-4.0, 4.0));
  p.mieScaleHeightKm = n.number("mie_scale_height", p.mieScaleHeightKm, Range::above(0.01));
  p.mieSingleScatteringAlbedo = n.number("mie_albedo", p.mieSingleScatteringAlbedo, Range::closed(0.0, 1.0));
  p.miePhaseG = n.number("mie_g", p.miePhaseG, Range::open(-1.0, 1.0));
  p.ozoneColumnDu = n.number("ozone", p.ozoneColumnDu, Range::closed(0.0, 1000.0));
  p.groundAlbedo = n.number("ground_albedo", p.groundAlbedo, Range::closed(0.0, 1.0));
  p.multipleScattering = n.boolean("multiple_scattering", p.multipleScattering);
  // What the height must hold, said at the keys the file has (validate's own words name
  // parameters a scene cannot set, such as the ozone layer's).
  const double height = p.topRadiusKm - p.bottomRadiusKm, ozoneTop = std::max(p.ozonePeakAltitudeKm, p.ozoneHalfWidthKm);
  if (height < ozoneTop)
    n.child("atmosphere_height").fail(fmt::format("{:g} km is below the ozone layer (peak at {:g} km, half-width {:g} km): "
                                                  "at least {:g}", height, p.ozonePeakAltitudeKm, p.ozoneHalfWidthKm, ozoneTop));
  for (const auto& [key, value] : {std::pair{"rayleigh_scale_height", p.rayleighScaleHeightKm},
                                   std::pair{"mie_scale_height", p.mieScaleHeightKm}})
    if (value > height)
      n.child(key).fail(fmt::format("{:g} km is above the atmosphere's height ({:g} km)", value, height));
  try {
    validate(p);
  } catch (const Error& e) {
    n.fail(e.what());
  }
  if (a.groundAltitudeM * 1e-3 >= p.topRadiusKm - p.bottomRadiusKm) {
    n.child("ground_altitude").fail(fmt::format("{} m must be below the top of the atmosphere ({} km)",
                                                a.groundAltitudeM, p.topRadiusKm - p.bottomRadiusKm));
  }
}

std::unique_ptr<TechniqueSection> AtmosphereSection::parse(const schema::Node& n,
                                                           const TechniqueSections& earlier) {
  if (earlier.has("water")) n.fail("a scene has water or an atmosphere, not both");
  auto a = std::make_unique<AtmosphereSection>();
  readAtmosphereKeys(n, *a);
  return a;
}

TechniqueBench AtmosphereSection::bench(std::size_t /*pointAndSpotLights*/) const {
  return {{{"optimised4", {{"mode", "optimised4"}}}, {"reference", {{"mode", "reference"}}, false, 1}},
          {{"ratio_optimised4_to_rgb3", "optimised4", "rgb"}, {"ratio_reference_to_optimised4", "reference", "optimised4"}}};
}

std::optional<TechniqueWavelengths> AtmosphereSection::optimisedWavelengths() const {
  OptimisedWavelengths set = loadOptimisedWavelengths(parameters.aerosols ? "aerosols" : "rayleigh-ozone");
  return TechniqueWavelengths{set.lambdaNm, set.weights};
}

}  // namespace prism::atmosphere
