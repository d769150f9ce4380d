// The scene file's "atmosphere" section (docs/scene-format.md): a planet's atmosphere around the
// scene. The sky is the background, the sun a directional light the section adds to the scene
// (the measured solar spectrum above the atmosphere, attenuated per point by the sky's
// transmittance), and the sky lights the surfaces (shaders/shared/atmosphere_lighting.glsl,
// under PRISM_TECHNIQUE_ATMOSPHERE). A scene has water or an atmosphere, not both.
#pragma once

#include <memory>
#include <string_view>
#include <vector>

#include "techniques/atmosphere/atmosphere_parameters.h"
#include "techniques/technique_section.h"

namespace prism::atmosphere {

// What the section describes, as plain data (another technique's sky holds one too: PRT's).
struct AtmosphereSky {
  AtmosphereParameters parameters;
  float sunElevationDeg = 20.0f;  // above the horizon, within ±kSunElevationLimitDeg
  float sunAzimuthDeg = 180.0f;   // 0: towards −z, 90: towards +x; within ±kSunAzimuthLimitDeg
  static constexpr float kSunElevationLimitDeg = 90.0f, kSunAzimuthLimitDeg = 360.0f;
  float groundAltitudeM = 0.0f;   // height of the world's y = 0 above the ground

  // Unit direction towards the sun (world, y up).
  glm::vec3 sunDirection() const;
  // Distance of the world's origin from the planet's centre.
  double originKm() const { return parameters.bottomRadiusKm + groundAltitudeM * 1e-3; }
};

struct AtmosphereSection final : TechniqueSection, AtmosphereSky {
  static constexpr std::string_view kKey = "atmosphere";

  std::string_view key() const override { return kKey; }
  std::string_view shaderDefine() const override { return "PRISM_TECHNIQUE_ATMOSPHERE"; }
  std::unique_ptr<TechniqueSection> clone() const override { return std::make_unique<AtmosphereSection>(*this); }
  // The sun: the solar spectrum at the top of the atmosphere, casting shadows.
  std::optional<TechniqueLight> light() const override;
  // SkyConstants (the origin's distance from the planet's centre, the sun light's index) and, per
  // batch, the GpuAtmosphere of atmosphere_model.glsl. The sun's irradiance above the atmosphere
  // is the sun light's own (its SPD × intensity: the measured solar spectrum unless edited; in
  // RGB mode its RGB, at 680, 550 and 440 nm, the RGB-3 strategy of sky_strategy.h), so that the
  // sky follows the light. Error when the scene lost its sun light.
  TechniqueBlock pack(const FramePackInput& input) const override;
  // García Liñán's four optimised wavelengths against RGB-3 (the run's RGB frames) and against the
  // reference (472 wavelengths, 118 batches of tables a frame: one frame a round), every table
  // recomputed every frame.
  TechniqueBench bench(std::size_t pointAndSpotLights) const override;
  // García Liñán's four for its atmosphere (data/atmosphere_wavelengths.json: with aerosols or
  // Rayleigh and ozone alone).
  std::optional<TechniqueWavelengths> optimisedWavelengths() const override;
  std::string_view notTracedBecause() const override {
    return "the path tracer does not trace the atmosphere; its references are `prism atmosphere evaluate` "
           "and `prism render --mode reference`";
  }

  static std::unique_ptr<TechniqueSection> parse(const schema::Node& node, const TechniqueSections& earlier);
};

// Reads the section's keys (docs/scene-format.md, "atmosphere") into `a`, which holds the
// defaults; `extraKeys` are allowed beside them (PRT's sky environment adds its own). Errors
// name the key's JSON pointer.
void readAtmosphereKeys(const schema::Node& n, AtmosphereSky& a, std::vector<std::string_view> extraKeys = {});

}  // namespace prism::atmosphere
