// The sky's tables on the GPU, recomputed whenever asked (every frame, so that the sun and the
// atmosphere can change live): for each batch of four wavelengths, the transmittance table,
// the multiple-scattering table and the sky-view table seen from the camera, each a layer of a
// texture array, then the sky's irradiance (four spherical-harmonic coefficients per batch, a
// storage buffer) and the aerial-perspective volume (one array: batches side by side in x, layer
// j·32 + slice, j 0 in-scattering, 1 transmittance), by the compute passes
// shaders/passes/atmosphere_*.comp over the same shaders/shared/atmosphere_*.glsl the CPU twin
// (techniques/atmosphere/atmosphere_tables.h) runs. The transmittance tables are combined from one
// integration of the constituents' optical depths (the densities table): the integration, about
// 30 M samples, was most of a batch's work, and the reference's 118 batches repeated it 118 times.
// All batches of an update are one atmosphere's (the same shape; checked). Tests hold the tables
// to the double-precision reference.
#pragma once

#include <memory>
#include <vector>

#include <glm/glm.hpp>

#include "gpu/buffer.h"
#include "gpu/program.h"
#include "gpu/texture.h"
#include "techniques/technique_pass.h"
#include "techniques/atmosphere/atmosphere_layout.h"

namespace prism::atmosphere {

// Where the frame is seen from (see shaders/shared/atmosphere_lighting.glsl for the frames).
struct AtmosphereView {
  float originKm = 6360.0f;      // distance of the world's origin from the planet's centre
  glm::vec3 cameraWorldM{0.0f};  // the camera, world metres
  glm::mat4 inverseViewProjection{1.0f};
  glm::vec3 sun{0.0f, 1.0f, 0.0f};  // unit, towards the sun
  float cameraRadiusKm() const;
};

class AtmospherePass final : public TechniquePass {
 public:
  AtmospherePass();  // compiles the passes (a context must be current)

  // Every table for these batches and this view. Textures are reallocated when the batch count
  // changes.
  void update(const std::vector<shared::GpuAtmosphere>& batches, const AtmosphereView& view);

  // The seam: update() from the sky's block (its batches, origin and sun light) and the camera;
  // the lighting pass reads the sky irradiance and the tables.
  void run(const TechniqueBlock& block, const Scene& scene, const CameraTransform& camera,
           const TechniqueFrame& frame) override;
  void bindForLighting() const override;
  std::size_t gpuMemoryBytes() const override;
  // The tables and the sky irradiance as AtmosphereTexels.
  std::shared_ptr<const TechniqueTexels> readTexels() const override;

  const gpu::Texture2DArray& transmittance() const { return mTransmittance; }  // optical depth
  const gpu::Texture2DArray& multipleScattering() const { return mMultipleScattering; }
  const gpu::Texture2DArray& skyView() const { return mSkyView; }
  const gpu::Texture2DArray& aerialPerspective() const { return mAerialPerspective; }
  const gpu::Buffer& skyIrradiance() const { return mSkyIrradiance; }  // vec4 × 4 per batch

 private:
  gpu::Program mDensitiesProgram, mTransmittanceProgram, mMultipleScatteringProgram, mSkyViewProgram,
      mSkyIrradianceProgram, mAerialPerspectiveProgram;
  gpu::Buffer mAtmospheres, mSkyIrradiance;
  gpu::Texture2DArray mDensities, mTransmittance, mMultipleScattering, mSkyView, mAerialPerspective;
  int mBatches = 0;
};

}  // namespace prism::atmosphere
