// The scene file's "water" section (docs/scene-format.md): the camera under water in a Jerlov
// water type (jerlov_water.h), its depth below the surface (which lies depthM above the camera:
// everything in the scene moves down with it) and multipliers of each coefficient. The
// rasteriser applies Pérez García's analytic model (shaders/shared/underwater.glsl, under
// PRISM_TECHNIQUE_WATER); the reference traces the same water as a medium below the surface.
#pragma once

#include <memory>
#include <string>

#include "techniques/technique_section.h"

namespace prism::underwater {

struct WaterSection final : TechniqueSection {
  static constexpr std::string_view kKey = "water";

  std::string type = "I";
  std::string dataset = "jerlov";  // or "williamson2022"
  float depthM = 5.0f;             // of the camera
  float scatteringScale = 1.0f;
  float absorptionScale = 1.0f;
  float kdScale = 1.0f;
  // Point and spot lamps scatter their light into the view (a torch's glow and beam); off, the
  // rasteriser leaves it out for speed (the reference always traces it).
  bool lampScattering = true;
  // Resolved from the above, multipliers applied (resolve()): 1/m.
  Spectrum sigmaA;
  Spectrum sigmaS;
  Spectrum kd;

  // World height of the surface for a camera at height cameraY (m).
  float surfaceY(float cameraY) const { return cameraY + depthM; }
  // Fills sigmaA, sigmaS and kd from the type, data set and multipliers (after a parse or an
  // editor's change). Error naming the type or data set when unknown.
  void resolve();

  std::string_view key() const override { return kKey; }
  std::string_view shaderDefine() const override { return "PRISM_TECHNIQUE_WATER"; }
  std::unique_ptr<TechniqueSection> clone() const override { return std::make_unique<WaterSection>(*this); }
  // WaterConstants (the surface, the camera's depth below it, whether lamps scatter) and, per batch, σs, σt = σa + σs
  // and Kd at its wavelengths (in RGB mode at 680, 550 and 440 nm, the wavelengths RGB renderers
  // commonly stand R, G and B for), then the environment's light from above as the frame gives it
  // (FramePackInput::environmentFromAbove; 0 without): underwater.glsl's layout.
  TechniqueBlock pack(const FramePackInput& input) const override;
  // Everything below the surface, scattering isotropically as the analytic model assumes, with
  // its Kd (by which PRT's forward pass dims the environment reaching its objects).
  std::optional<TechniqueMedium> medium(const glm::vec3& sceneCameraPositionW) const override;
  // The water term's cost: the same frames with the water taken out, RGB and 16 wavelengths; and
  // the lamps' in-scattering's, 16 wavelengths with it left out (where lampScattering is on and
  // the scene has a point or spot lamp).
  TechniqueBench bench(std::size_t pointAndSpotLights) const override;

  static std::unique_ptr<TechniqueSection> parse(const schema::Node& node, const TechniqueSections& earlier);
};

}  // namespace prism::underwater
