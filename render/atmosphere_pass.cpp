#include "render/atmosphere_pass.h"

#include <span>

#include "gpu/compute.h"
#include "spectral/data_files.h"

namespace prism::render {
namespace {

gpu::Program computeProgram(const char* file, const char* label) {
  gpu::ProgramDesc desc;
  desc.compute = shaderDirectory() / "passes" / file;
  desc.includeDirs = {shaderDirectory()};
  desc.label = label;
  return gpu::Program(desc);
}

gpu::Texture2DArray table(int width, int height, int layers, const char* label) {
  gpu::Texture2DArrayDesc desc;
  desc.width = width;
  desc.height = height;
  desc.layers = layers;
  desc.internalFormat = GL_RGBA32F;
  desc.sampling.minFilter = GL_NEAREST;
  desc.sampling.magFilter = GL_NEAREST;
  desc.label = label;
  return gpu::Texture2DArray(desc);
}

GLuint groups(int size) { return static_cast<GLuint>((size + 7) / 8); }

}  // namespace

AtmospherePass::AtmospherePass()
    : mTransmittanceProgram(computeProgram("atmosphere_transmittance.comp", "atmosphere transmittance")),
      mMultipleScatteringProgram(
          computeProgram("atmosphere_multiple_scattering.comp", "atmosphere multiple scattering")),
      mSkyViewProgram(computeProgram("atmosphere_sky_view.comp", "atmosphere sky view")) {}

void AtmospherePass::update(const std::vector<shared::GpuAtmosphere>& batches, float cameraRadiusKm,
                            float muSun) {
  const int n = static_cast<int>(batches.size());
  if (n != mBatches) {
    mTransmittance = table(shared::kTransmittanceLutWidth, shared::kTransmittanceLutHeight, n,
                           "atmosphere transmittance");
    mMultipleScattering = table(shared::kMultipleScatteringLutSize, shared::kMultipleScatteringLutSize,
                                n, "atmosphere multiple scattering");
    mSkyView = table(shared::kSkyViewLutWidth, shared::kSkyViewLutHeight, n, "atmosphere sky view");
    mBatches = n;
  }
  mAtmospheres = gpu::Buffer::fromSpan(std::span<const shared::GpuAtmosphere>(batches), "atmospheres");
  mAtmospheres.bindBase(GL_SHADER_STORAGE_BUFFER, 0);
  const GLbitfield barriers = GL_TEXTURE_FETCH_BARRIER_BIT | GL_SHADER_IMAGE_ACCESS_BARRIER_BIT;
  const GLuint layers = static_cast<GLuint>(n);

  mTransmittance.bindImage(0, GL_WRITE_ONLY);
  gpu::runCompute(mTransmittanceProgram,
                  {groups(shared::kTransmittanceLutWidth), groups(shared::kTransmittanceLutHeight), layers},
                  barriers);
  mTransmittance.bind(0);
  mMultipleScattering.bind(1);
  mMultipleScattering.bindImage(0, GL_WRITE_ONLY);
  gpu::runCompute(mMultipleScatteringProgram,
                  {groups(shared::kMultipleScatteringLutSize), groups(shared::kMultipleScatteringLutSize), layers},
                  barriers);
  mSkyView.bindImage(0, GL_WRITE_ONLY);
  mSkyViewProgram.setUniform("uCameraRadiusKm", cameraRadiusKm);
  mSkyViewProgram.setUniform("uMuSun", muSun);
  gpu::runCompute(mSkyViewProgram,
                  {groups(shared::kSkyViewLutWidth), groups(shared::kSkyViewLutHeight), layers}, barriers);
}

}  // namespace prism::render
