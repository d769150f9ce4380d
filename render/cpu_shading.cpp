#include "render/cpu_shading.h"

#include <utility>

namespace prism::shared {

// pixel_shading.glsl compiled inside a class whose members are its accessors.
class CpuShadingKernel {
 public:
  CpuShadingKernel(const render::FrameData& frame, const RgbToSpectrumTable& table,
                   std::vector<std::vector<float>> shadowLayers, render::AtmosphereTexels atmosphere)
      : mFrame(frame), mTable(table), mShadowLayers(std::move(shadowLayers)), mAtmosphere(std::move(atmosphere)) {}

  vec3 shade(const render::GBufferTexel& texel, vec2 uv, const CameraTransform& camera) {
    if (texel.materialId == 0) {
      return shadeBackground(mFrame.constants, worldFromDepth(camera.inverseViewProjection, uv, 1.0f),
                             camera.position);
    }
    SurfaceSample s;
    s.position = worldFromDepth(camera.inverseViewProjection, uv, texel.depth);
    s.normal = normalize(vec3(texel.normalRoughness));
    s.albedo = vec3(texel.albedoMetallic);
    s.metallic = texel.albedoMetallic.w;
    s.roughness = texel.normalRoughness.w;
    s.material = static_cast<int>(texel.materialId) - 1;
    mTexelCoefficients = texel.coefficients;
    return shadeSurface(mFrame.constants, s, camera.position, uv);
  }

 private:
  static std::size_t index(int i) { return static_cast<std::size_t>(i); }
  GpuBatch frameBatch(int b) const { return mFrame.batches[index(b)]; }
  GpuLight frameLight(int l) const { return mFrame.lights[index(l)]; }
  GpuMaterial frameMaterial(int id) const { return mFrame.materials[index(id)]; }
  vec4 frameLightSpectrum(int l, int b) const {
    return mFrame.lightSpectra[index(lightSpectrumIndex(l, b, mFrame.constants.batchCount))];
  }
  vec4 frameMaterialSpectrum(int s, int b, int j) const {
    return mFrame.materialSpectra[index(materialSpectrumIndex(s, b, j, mFrame.constants.batchCount))];
  }
  float shadowDepthAt(int layer, int x, int y) const {
    return mShadowLayers[index(layer)][index(y * mFrame.constants.shadowMapSize + x)];
  }
  vec3 upsamplingCoefficients(vec3 rgb) const {
    return mFrame.constants.gbufferCoefficients != 0 ? mTexelCoefficients : mTable.lookup(rgb);
  }
  vec4 frameWaterSpectrum(int b, int j) const { return mFrame.waterSpectra[index(waterSpectrumIndex(b, j))]; }
  GpuAtmosphere frameAtmosphere(int b) const { return mFrame.atmospheres[index(b)]; }
  static vec4 texel(const std::vector<std::vector<glm::vec4>>& layers, int layer, int x, int y, int width) {
    return layers[index(layer)][index(y * width + x)];
  }
  vec4 transmittanceLutTexel(int b, int x, int y) const {
    return texel(mAtmosphere.transmittance, b, x, y, kTransmittanceLutWidth);
  }
  vec4 multipleScatteringLutTexel(int b, int x, int y) const {
    return texel(mAtmosphere.multipleScattering, b, x, y, kMultipleScatteringLutSize);
  }
  vec4 skyViewLutTexel(int b, int x, int y) const { return texel(mAtmosphere.skyView, b, x, y, kSkyViewLutWidth); }
  vec4 aerialPerspectiveTexel(int b, int x, int y, int slice, int j) const {
    return texel(mAtmosphere.aerialPerspective, j * kAerialPerspectiveSlices + slice,
                 b * kAerialPerspectiveSize + x, y, kAerialPerspectiveSize * mFrame.constants.batchCount);
  }
  vec4 skyIrradianceCoefficient(int b, int k) const { return mAtmosphere.skyIrradiance[index(b * 4 + k)]; }

#include "atmosphere_luts.glsl"
#include "atmosphere_lighting.glsl"
#include "pixel_shading.glsl"

  render::FrameData mFrame;
  const RgbToSpectrumTable& mTable;
  std::vector<std::vector<float>> mShadowLayers;
  render::AtmosphereTexels mAtmosphere;
  vec3 mTexelCoefficients{0.0f};  // of the texel being shaded
};

}  // namespace prism::shared

namespace prism::render {

struct CpuShading::Kernel : shared::CpuShadingKernel {
  using CpuShadingKernel::CpuShadingKernel;
};

CpuShading::CpuShading(const FrameData& frame, const RgbToSpectrumTable& table,
                       std::vector<std::vector<float>> shadowLayers, AtmosphereTexels atmosphere)
    : mKernel(std::make_unique<Kernel>(frame, table, std::move(shadowLayers), std::move(atmosphere))) {}

CpuShading::~CpuShading() = default;

glm::vec3 CpuShading::shade(const GBufferTexel& texel, const glm::vec2& uv,
                            const CameraTransform& camera) {
  return mKernel->shade(texel, uv, camera);
}

}  // namespace prism::render
