// A nebula in a scene of the renderer: the scene file's "nebula" section (the keys of a nebula
// scene file but its camera, nebula_scene.h, plus where the unit cube lies in the world, the
// method, the basis size and the intensity). The renderer's camera looks through it: the GPU
// marcher's pass (gpu/nebula_pass.h) marches every pixel up to the scene's depth and adds the
// nebula's channels to the frame's tristimulus, after the lighting pass.
//
// Its channels are its filters': "cie1931" gives the CIE 1931 XYZ of the light, added as the
// frame's XYZ; "hubble" gives the palette's R, G, B, added as linear sRGB (Rec. 709, D65) turned
// to XYZ. Either is times `intensity` (cd/m² of Y per unit of the nebula's channels).
//
// Its stars light the scene's surfaces (`light_surfaces`, on by default), each a point light of
// the radiant intensity that gives the nebula's own light in natural colour: I(λ) = intensity·L·
// size²·S(λ)/(4π·683·1000) W·sr⁻¹·nm⁻¹ (starRadiantIntensity; S the star's normalised spectrum in
// µm⁻¹), dimmed by the dust between (shared/nebula_lighting.glsl). The nebula
// is its own reference (the paper's double integration, the renderer's reference mode), so the
// path tracer refuses it.
#pragma once

#include <memory>
#include <string>
#include <string_view>

#include <glm/glm.hpp>

#include "techniques/nebula/nebula_scene.h"
#include "techniques/technique_section.h"

namespace prism::nebula {

struct NebulaSection final : TechniqueSection {
  static constexpr std::string_view kKey = "nebula";

  // The model but its camera (the renderer's) and its density, which `density` holds so that
  // copies of the scene share it; noise is generated at the precomputation (the pass's), not as
  // the scene loads.
  NebulaModel model;
  std::shared_ptr<const DeferredDensity> density = std::make_shared<DeferredDensity>(DensityGrid{});
  DensitySource source;
  int steps = 100;
  Method method = Method::Projection;  // any of the five, all marched on the GPU
  int basis = 4;                       // card(B), 1..6
  double basisDepthUm = 2.0;           // the basis's family: e^(−g/λ) for g up to this (µm), (0, 16]
  // The reference's wavelengths: 0, composite Simpson over each passband piece (the ground
  // truth); n, n per channel by the trapezoid rule (7: the paper's baseline, 21 a step).
  int referenceSamples = 0;
  glm::vec3 boxMin{0.0f};              // the unit cube's corner in the world (m)
  float boxSize = 1.0f;                // its side (m)
  float intensity = 1.0f;
  // March every frame, not only when the view or the section changed: what a moving camera
  // costs (the bench's configurations; scene key "march_every_frame").
  bool marchEveryFrame = false;
  // Its stars light the scene's surfaces (scene key "light_surfaces").
  bool lightSurfaces = true;

  std::string_view key() const override { return kKey; }
  std::string_view shaderDefine() const override { return "PRISM_TECHNIQUE_NEBULA"; }
  std::unique_ptr<TechniqueSection> clone() const override { return std::make_unique<NebulaSection>(*this); }
  // The stars' lights (shared/nebula_lighting.glsl's block); the pass uploads what it marches
  // when the section changes.
  TechniqueBlock pack(const FramePackInput& input) const override;
  // A star's radiant intensity (W·sr⁻¹·nm⁻¹): its light as the nebula's natural colour sees it,
  // whatever the filters (the header says why).
  Spectrum starRadiantIntensity(const NebulaStar& star) const;
  // Where the star is in the world (m).
  glm::vec3 starPositionW(const NebulaStar& star) const;
  std::string_view notTracedBecause() const override;
  // A density file's grid, its size and values; nothing for noise, whose parameters are in the
  // scene file.
  std::uint64_t hashLoadedData(std::uint64_t hash) const override;
  std::vector<std::filesystem::path> inputFiles() const override;  // the density file, when there is one
  // The section's method against the others on this scene, the nebula's pass timed in each,
  // marching every frame: the reference at the paper's settings (100 steps, 21 wavelengths a step)
  // over projection and over light–density (prism bench's ratios); and, the camera held so that
  // the march runs once, the stars lighting the surfaces over not.
  TechniqueBench bench(std::size_t pointAndSpotLights) const override;

  // The model with the density (generated now if it was not), as a NebulaRenderer takes it.
  NebulaModel fullModel() const;
  // The render settings of the section (its method, steps, basis and reference wavelengths).
  RenderSettings renderSettings() const;
  // Everything the pass's precomputation depends on (not the method, the steps or the intensity),
  // as text: the pass rebuilds its NebulaRenderer when it changes.
  std::string precomputationKey() const;
  // The same but the filters and passbands: when only those changed, the pass refilters its
  // NebulaRenderer (milliseconds) instead of building it again.
  std::string volumeKey() const;
  // A new density from `source.noise` (an editor changed it), generated at its first use; no-op
  // for a file.
  void regenerateDensity();

  static std::unique_ptr<TechniqueSection> parse(const schema::Node& node, const TechniqueSections& earlier);

 private:
  // I(λ) per unit of the star's normalised spectrum S(λ) (µm⁻¹).
  double starRadiantScale(const NebulaStar& star) const;
};

}  // namespace prism::nebula
