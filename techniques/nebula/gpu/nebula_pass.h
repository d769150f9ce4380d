// The nebula technique's GPU half. Before the lighting pass (run), the GPU marcher
// (nebula_gpu_marcher.h) marches the scene's nebula from the renderer's camera, each ray stopping
// at the scene's surfaces (the G-buffer's depth), into the nebula's channels and the optical depth
// in front of each pixel, which the lighting pass reads (bindForLighting) to dim what lies behind
// by e^(−g/λ), beside the stars' optical depths per voxel, which dim the stars' light on surfaces
// (shared/nebula_lighting.glsl). After it (drawForward), a fullscreen draw adds the
// channels to the frame's tristimulus (nebula_section.h says how), so that the post pass
// finishes the nebula with the rest.
//
// The method is the section's; the renderer's reference mode marches the reference (the paper's
// double integration, the nebula's ground truth). The precomputation (a NebulaRenderer: filters,
// stars' spectra, each star's optical depth per voxel, the bases) is made ahead with a progress
// bar (precompute, from render, bench and view) or on first use, and again when the section's
// model changes; the march runs again only when the camera or the section's settings change, so
// frames accumulating a still view add the same image. A change of the filters or passbands alone
// refilters: the precomputation is copied with new filters (milliseconds), and after projection or
// light–density the marcher's moments stand and only its finish runs again, no march.
#pragma once

#include <memory>
#include <string>

#include "gpu/program.h"
#include "gpu/vertex_array.h"
#include "techniques/nebula/gpu/nebula_gpu_marcher.h"
#include "techniques/nebula/nebula_section.h"
#include "techniques/technique_pass.h"

namespace prism::nebula {

class NebulaPass final : public TechniquePass {
 public:
  NebulaPass();
  // The scene's nebula precomputed into a process-wide memo (the last section's), which the pass
  // then takes instead of computing it again.
  static void precompute(const Scene& scene, const TechniqueProgress& progress);
  // The stars' optical depths in this GPU's 3D textures (requireTechniquesFit), named at
  // /nebula/stars, where they are read: every method but light-density, and where the stars light
  // surfaces. run() checks it too at every frame (the renderer's reference mode marches the
  // reference), before a precomputation of its own.
  static void requireFits(const Scene& scene);
  void run(const TechniqueBlock& block, const Scene& scene, const CameraTransform& camera,
           const TechniqueFrame& frame) override;
  void bindForLighting() const override;
  // The optical depth the lighting pass reads and the precomputation whose star depths it reads
  // (NebulaTexels). Stalls: for tests.
  std::shared_ptr<const TechniqueTexels> readTexels() const override;
  std::size_t gpuMemoryBytes() const override;
  bool drawsForward() const override { return true; }
  void drawForward(const ForwardDrawInput& input) override;

  // The last march's settings and marcher (for tests: the CPU marcher's twin).
  const RenderSettings& lastSettings() const { return mSettings; }
  const NebulaGpuMarcher* marcher() const { return mMarcher.get(); }
  // Marches made so far (a still view marches once).
  int marches() const { return mMarches; }

 private:
  gpu::Program mComposite;
  gpu::VertexArray mEmpty;
  std::shared_ptr<const NebulaRenderer> mRenderer;
  std::unique_ptr<NebulaGpuMarcher> mMarcher;
  std::string mPrecomputationKey, mVolumeKey, mMarchKey;
  MarchView mView;
  RenderSettings mSettings;
  int mMarches = 0;
  bool mStarsLightSurfaces = false;  // the lighting pass reads the stars' depths (bindForLighting)
};

}  // namespace prism::nebula
