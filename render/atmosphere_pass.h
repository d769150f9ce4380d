// The sky's tables on the GPU, recomputed whenever asked (every frame, so that the sun and the
// atmosphere can change live): for each batch of four wavelengths, the transmittance table,
// the multiple-scattering table and the sky-view table seen from the camera, each a layer of a
// texture array, by the compute passes shaders/passes/atmosphere_*.comp over the same
// shaders/shared/atmosphere_luts.glsl the CPU twin (techniques/atmosphere/atmosphere_tables.h)
// runs. Tests hold them to the double-precision reference.
#pragma once

#include <vector>

#include "gpu/buffer.h"
#include "gpu/program.h"
#include "gpu/texture.h"
#include "techniques/atmosphere/atmosphere_layout.h"

namespace prism::render {

class AtmospherePass {
 public:
  AtmospherePass();  // compiles the passes (a context must be current)

  // All three tables for these batches, the camera at radius cameraRadiusKm under a sun of
  // zenith cosine muSun. Textures are reallocated when the batch count changes.
  void update(const std::vector<shared::GpuAtmosphere>& batches, float cameraRadiusKm, float muSun);

  const gpu::Texture2DArray& transmittance() const { return mTransmittance; }  // optical depth
  const gpu::Texture2DArray& multipleScattering() const { return mMultipleScattering; }
  const gpu::Texture2DArray& skyView() const { return mSkyView; }

 private:
  gpu::Program mTransmittanceProgram, mMultipleScatteringProgram, mSkyViewProgram;
  gpu::Buffer mAtmospheres;
  gpu::Texture2DArray mTransmittance, mMultipleScattering, mSkyView;
  int mBatches = 0;
};

}  // namespace prism::render
