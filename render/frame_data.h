// The lighting pass's per-frame inputs, built on the CPU: the wavelength batches and their
// integration matrices, the lights, the material table and every spectrum evaluated at this
// frame's wavelengths (see shaders/shared/frame_layout.glsl for the layout). The GPU uploads it
// as it is; the CPU twin (cpu_shading.h) reads the same arrays.
//
// Conversions per mode, one place:
// - Lights: SPD (normalised photometrically) at each wavelength; in RGB mode the SPD's own
//   linear RGB in the scene's colour space (Y = 1), the colour an RGB engine would be given.
// - Materials: measured reflectance at each wavelength (RGB mode: its colour under the colour
//   space's white, the light its upsampling table is fitted under: D65, or D60 for ACES);
//   conductors n and k at each wavelength, never upsampled (RGB mode: F0 = the normal-incidence
//   reflectance's colour under that white, rendered with Schlick).
// - Background: a light colour (RGB mode: rgb × luminance; spectral: its RgbIlluminantSpectrum,
//   scene/scene_spectra.h: the colour space's white times the unbounded upsampling of the
//   colour, so a white background is that white, not a flat spectrum).
// - Integration: the observer's curves over n·pdf, times 683 lm/W, so tristimulus is absolute
//   (Y in cd/m²). A camera observer is scaled so that its green of D65 equals D65's Y; the post
//   pass maps camera RGB to XYZ with the fitted camera matrix. RGB mode integrates with the
//   colour space's RGB → XYZ rows.
// - Techniques (water, the sky, …): each section packs its own block (its constants and its
//   per-batch data, techniques/technique_section.h), in the order of the scene's sections.
#pragma once

#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "render/frame_context.h"
#include "render/frame_settings.h"
#include "scene/camera_transform.h"
#include "scene/scene.h"
#include "render/shadow_views.h"
#include "render/shared_shading.h"
#include "techniques/technique_section.h"
#include "spectral/rgb_to_spectrum_table.h"

namespace prism::render {

struct FrameData {
  shared::FrameConstants constants{};
  std::vector<shared::GpuBatch> batches;
  std::vector<shared::GpuLight> lights;
  std::vector<shared::GpuMaterial> materials;  // one per scene material, in scene order
  std::vector<glm::vec4> lightSpectra;         // (lightCount + 1) × batchCount
  std::vector<glm::vec4> materialSpectra;      // spectra × batchCount × 2 (at least one entry)
  std::vector<TechniqueBlock> techniques;      // one per technique section of the scene

  // The block of the technique of that key; null when the scene has no such section.
  const TechniqueBlock* technique(std::string_view key) const {
    for (const TechniqueBlock& block : techniques)
      if (block.key == key) return &block;
    return nullptr;
  }
};

// Error "SCENE: /lights: N lights (M in the file, and the atmosphere's sun); the renderer handles
// at most kMaxLights" (the parenthesis only where a technique added lights) when the scene has more than the lighting pass takes; the lights a
// technique adds (the sky's sun) count, and are named.
void requireLightCount(const Scene& scene);

// Error when one of the scene's techniques cannot show a frame of these settings (PRT's rgb-prt
// mode under a camera's curves), or the optimised4 mode has no technique's wavelengths to render:
// the renderer's own check, which callers make before the work ahead of it too.
void requireTechniquesShow(const Scene& scene, const FrameSettings& settings);

// context holds settings' names resolved and the wavelength sampler (frameContext). frameIndex
// seeds the wavelength strategies that change between frames (a new set every frame). camera is
// where the frame is seen from (the water's depth there; the surface stays where the scene put it).
FrameData buildFrameData(const Scene& scene, const FrameSettings& settings, const FrameContext& context,
                         const RgbToSpectrumTable& table, const std::vector<ShadowView>& shadows,
                         std::uint32_t frameIndex, const CameraTransform& camera);

}  // namespace prism::render
