#include "techniques/atmosphere/gpu/atmosphere_pass.h"

#include <span>
#include <utility>

#include "gpu/compute.h"
#include "techniques/atmosphere/atmosphere_section.h"
#include "techniques/atmosphere/atmosphere_texels.h"
#include "core/data_files.h"
#include "core/error.h"

namespace prism::atmosphere {
namespace {

std::vector<std::vector<glm::vec4>> readLayers(const gpu::Texture2DArray& t) {
  std::vector<std::vector<glm::vec4>> layers;
  for (GLint l = 0; l < t.layers(); ++l) {
    std::vector<float> v = gpu::readTextureLayerFloat(t, l, 4);
    std::vector<glm::vec4> texels(v.size() / 4);
    for (std::size_t i = 0; i < texels.size(); ++i) texels[i] = glm::vec4(v[4 * i], v[4 * i + 1], v[4 * i + 2], v[4 * i + 3]);
    layers.push_back(std::move(texels));
  }
  return layers;
}

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
    : mDensitiesProgram(
          computeProgram("atmosphere_transmittance_densities.comp", "atmosphere transmittance densities")),
      mTransmittanceProgram(computeProgram("atmosphere_transmittance.comp", "atmosphere transmittance")),
      mMultipleScatteringProgram(
          computeProgram("atmosphere_multiple_scattering.comp", "atmosphere multiple scattering")),
      mSkyViewProgram(computeProgram("atmosphere_sky_view.comp", "atmosphere sky view")),
      mSkyIrradianceProgram(computeProgram("atmosphere_sky_irradiance.comp", "atmosphere sky irradiance")),
      mAerialPerspectiveProgram(
          computeProgram("atmosphere_aerial_perspective.comp", "atmosphere aerial perspective")),
      mDensities(table(shared::kTransmittanceLutWidth, shared::kTransmittanceLutHeight, 1,
                       "atmosphere transmittance densities")) {}

float AtmosphereView::cameraRadiusKm() const {
  return glm::length(glm::vec3(cameraWorldM.x * 1e-3f, originKm + cameraWorldM.y * 1e-3f, cameraWorldM.z * 1e-3f));
}

void AtmospherePass::update(const std::vector<shared::GpuAtmosphere>& batches, const AtmosphereView& view) {
  const int n = static_cast<int>(batches.size());
  PRISM_CHECK(n > 0);
  // The densities are integrated over the first batch's shape: the others must share it.
  for (const shared::GpuAtmosphere& b : batches)
    PRISM_CHECK(b.shape == batches[0].shape && b.ozoneMie.x == batches[0].ozoneMie.x &&
                b.ozoneMie.y == batches[0].ozoneMie.y);
  if (n != mBatches) {
    mTransmittance = table(shared::kTransmittanceLutWidth, shared::kTransmittanceLutHeight, n,
                           "atmosphere transmittance");
    mMultipleScattering = table(shared::kMultipleScatteringLutSize, shared::kMultipleScatteringLutSize,
                                n, "atmosphere multiple scattering");
    mSkyView = table(shared::kSkyViewLutWidth, shared::kSkyViewLutHeight, n, "atmosphere sky view");
    mAerialPerspective = table(shared::kAerialPerspectiveSize * n, shared::kAerialPerspectiveSize,
                               2 * shared::kAerialPerspectiveSlices, "atmosphere aerial perspective");
    mSkyIrradiance = gpu::Buffer(gpu::BufferDesc{static_cast<std::size_t>(n) * 4 * sizeof(glm::vec4), nullptr,
                                                 GL_DYNAMIC_STORAGE_BIT, "sky irradiance"});
    mAtmospheres = gpu::Buffer(gpu::BufferDesc{batches.size() * sizeof(shared::GpuAtmosphere), nullptr,
                                               GL_DYNAMIC_STORAGE_BIT, "atmospheres"});
    mBatches = n;
  }
  mAtmospheres.upload(0, std::as_bytes(std::span<const shared::GpuAtmosphere>(batches)));
  mAtmospheres.bindBase(GL_SHADER_STORAGE_BUFFER, 0);
  // Later passes fetch the tables; tests read them back (texture and buffer updates).
  const GLbitfield barriers = GL_TEXTURE_FETCH_BARRIER_BIT | GL_SHADER_IMAGE_ACCESS_BARRIER_BIT |
                              GL_TEXTURE_UPDATE_BARRIER_BIT | GL_BUFFER_UPDATE_BARRIER_BIT;
  const GLuint layers = static_cast<GLuint>(n);

  mDensities.bindImage(0, GL_WRITE_ONLY);
  gpu::runCompute(mDensitiesProgram,
                  {groups(shared::kTransmittanceLutWidth), groups(shared::kTransmittanceLutHeight), 1}, barriers);
  mTransmittance.bindImage(0, GL_WRITE_ONLY);
  mDensities.bindImage(1, GL_READ_ONLY);
  gpu::runCompute(mTransmittanceProgram,
                  {groups(shared::kTransmittanceLutWidth), groups(shared::kTransmittanceLutHeight), layers},
                  barriers);
  mTransmittance.bind(0);
  mMultipleScattering.bind(1);  // for the later passes; this one never reads it (see its shader)
  mMultipleScattering.bindImage(0, GL_WRITE_ONLY);
  gpu::runCompute(mMultipleScatteringProgram,
                  {groups(shared::kMultipleScatteringLutSize), groups(shared::kMultipleScatteringLutSize), layers},
                  barriers);
  const float cameraRadiusKm = view.cameraRadiusKm();
  mSkyView.bindImage(0, GL_WRITE_ONLY);
  mSkyViewProgram.setUniform("uCameraRadiusKm", cameraRadiusKm);
  mSkyViewProgram.setUniform("uMuSun", view.sun.y);  // the scene's up is y (atmosphere_lighting.glsl)
  gpu::runCompute(mSkyViewProgram,
                  {groups(shared::kSkyViewLutWidth), groups(shared::kSkyViewLutHeight), layers}, barriers);

  mSkyView.bind(2);
  mSkyIrradiance.bindBase(GL_SHADER_STORAGE_BUFFER, 1);
  mSkyIrradianceProgram.setUniform("uCameraRadiusKm", cameraRadiusKm);
  mSkyIrradianceProgram.setUniform("uSun", view.sun);
  gpu::runCompute(mSkyIrradianceProgram, {1, layers, 1}, barriers | GL_SHADER_STORAGE_BARRIER_BIT);

  mAerialPerspective.bindImage(0, GL_WRITE_ONLY);
  mAerialPerspectiveProgram.setUniform("uInverseViewProjection", view.inverseViewProjection);
  mAerialPerspectiveProgram.setUniform("uCameraWorld", view.cameraWorldM);
  mAerialPerspectiveProgram.setUniform("uOriginKm", view.originKm);
  mAerialPerspectiveProgram.setUniform("uSun", view.sun);
  gpu::runCompute(mAerialPerspectiveProgram,
                  {groups(shared::kAerialPerspectiveSize), groups(shared::kAerialPerspectiveSize), layers}, barriers);
}

void AtmospherePass::run(const TechniqueBlock& block, const Scene& scene, const CameraTransform& camera,
                         const TechniqueFrame&) {
  const auto sky = block.constantsAs<shared::SkyConstants>();
  std::vector<shared::GpuAtmosphere> batches;
  for (std::size_t b = 0; b < block.dataCount<shared::GpuAtmosphere>(); ++b) {
    batches.push_back(block.dataAt<shared::GpuAtmosphere>(b));
  }
  AtmosphereView view;
  view.originKm = sky.originKm;
  view.cameraWorldM = camera.position;
  view.inverseViewProjection = camera.inverseViewProjection;
  // The sun light is the one source of the sun's direction (an editor may turn it).
  view.sun = -glm::normalize(scene.lights.at(static_cast<std::size_t>(sky.sunLight)).direction);
  update(batches, view);
}

// Bindings of lighting.frag's sky section.
void AtmospherePass::bindForLighting() const {
  mSkyIrradiance.bindBase(GL_SHADER_STORAGE_BUFFER, 7);
  mTransmittance.bind(7);
  mMultipleScattering.bind(8);
  mSkyView.bind(9);
  mAerialPerspective.bind(10);
}

std::shared_ptr<const TechniqueTexels> AtmospherePass::readTexels() const {
  auto a = std::make_shared<AtmosphereTexels>();
  a->transmittance = readLayers(mTransmittance);
  a->multipleScattering = readLayers(mMultipleScattering);
  a->skyView = readLayers(mSkyView);
  a->aerialPerspective = readLayers(mAerialPerspective);
  a->skyIrradiance = mSkyIrradiance.read<glm::vec4>();
  return a;
}

std::size_t AtmospherePass::gpuMemoryBytes() const {
  std::size_t bytes = mSkyIrradiance.sizeBytes() + mAtmospheres.sizeBytes();
  for (const gpu::Texture2DArray* t : {&mDensities, &mTransmittance, &mMultipleScattering, &mSkyView, &mAerialPerspective}) {
    bytes += t->sizeBytes();
  }
  return bytes;
}

}  // namespace prism::atmosphere
