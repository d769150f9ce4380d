#include "render/cpu_shading.h"

#include <utility>

#include "techniques/atmosphere/atmosphere_section.h"
#include "techniques/underwater/water_section.h"

namespace prism::shared {

// The accessors pixel_shading.glsl reads, over the same FrameData the GPU reads, and the sky's
// tables (atmosphere_luts.glsl and atmosphere_lighting.glsl compiled over them).
class CpuShadingAccessors {
 public:
  CpuShadingAccessors(const render::FrameData& frame, const RgbToSpectrumTable& table,
                      std::vector<std::vector<float>> shadowLayers, render::AtmosphereTexels atmosphere)
      : mFrame(frame), mTable(table), mShadowLayers(std::move(shadowLayers)), mAtmosphere(std::move(atmosphere)) {
    if (const TechniqueBlock* water = mFrame.technique(underwater::WaterSection::kKey)) mWater = water;
    if (const TechniqueBlock* sky = mFrame.technique(atmosphere::AtmosphereSection::kKey)) mSky = sky;
  }
  virtual ~CpuShadingAccessors() = default;
  virtual vec3 shade(const render::GBufferTexel& texel, vec2 uv, const CameraTransform& camera) = 0;

 protected:
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
  WaterConstants frameWater() const { return mWater->constantsAs<WaterConstants>(); }
  vec4 frameWaterSpectrum(int b, int j) const { return mWater->dataAt<vec4>(index(waterSpectrumIndex(b, j))); }
  SkyConstants frameSky() const { return mSky->constantsAs<SkyConstants>(); }
  GpuAtmosphere frameAtmosphere(int b) const { return mSky->dataAt<GpuAtmosphere>(index(b)); }
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

  render::FrameData mFrame;
  const RgbToSpectrumTable& mTable;
  std::vector<std::vector<float>> mShadowLayers;
  render::AtmosphereTexels mAtmosphere;
  const TechniqueBlock* mWater = nullptr;  // in mFrame, when the scene has these techniques
  const TechniqueBlock* mSky = nullptr;
  vec3 mTexelCoefficients{0.0f};  // of the texel being shaded
};

// pixel_shading.glsl compiled inside a class whose base holds its accessors, once per variant of
// techniques, as the renderer compiles lighting.frag (PRISM_CPU_SHADING_VARIANT's body below).
#define PRISM_CPU_SHADING_VARIANT(Name)                                                              \
  class Name final : public CpuShadingAccessors {                                                    \
   public:                                                                                           \
    using CpuShadingAccessors::CpuShadingAccessors;                                                  \
    vec3 shade(const render::GBufferTexel& texel, vec2 uv, const CameraTransform& camera) override { \
      if (texel.materialId == 0) {                                                                   \
        return shadeBackground(mFrame.constants, worldFromDepth(camera.inverseViewProjection, uv, 1.0f), \
                               camera.position);                                                     \
      }                                                                                              \
      SurfaceSample s;                                                                               \
      s.position = worldFromDepth(camera.inverseViewProjection, uv, texel.depth);                    \
      s.normal = normalize(vec3(texel.normalRoughness));                                             \
      s.albedo = vec3(texel.albedoMetallic);                                                         \
      s.metallic = texel.albedoMetallic.w;                                                           \
      s.roughness = texel.normalRoughness.w;                                                         \
      s.material = static_cast<int>(texel.materialId) - 1;                                           \
      mTexelCoefficients = texel.coefficients;                                                       \
      return shadeSurface(mFrame.constants, s, camera.position, uv);                                 \
    }
// (each variant's class continues with the shared file and closes after it)

PRISM_CPU_SHADING_VARIANT(KernelPlain)
#include "pixel_shading.glsl"
};

#define PRISM_TECHNIQUE_WATER
PRISM_CPU_SHADING_VARIANT(KernelWater)
#include "pixel_shading.glsl"
};
#undef PRISM_TECHNIQUE_WATER

#define PRISM_TECHNIQUE_ATMOSPHERE
PRISM_CPU_SHADING_VARIANT(KernelAtmosphere)
#include "pixel_shading.glsl"
};

#define PRISM_TECHNIQUE_WATER
PRISM_CPU_SHADING_VARIANT(KernelWaterAtmosphere)
#include "pixel_shading.glsl"
};
#undef PRISM_TECHNIQUE_WATER
#undef PRISM_TECHNIQUE_ATMOSPHERE
#undef PRISM_CPU_SHADING_VARIANT

}  // namespace prism::shared

namespace prism::render {

struct CpuShading::Kernel {
  std::unique_ptr<shared::CpuShadingAccessors> variant;
};

CpuShading::CpuShading(const FrameData& frame, const RgbToSpectrumTable& table,
                       std::vector<std::vector<float>> shadowLayers, AtmosphereTexels atmosphere)
    : mKernel(std::make_unique<Kernel>()) {
  const bool water = frame.technique(underwater::WaterSection::kKey) != nullptr, sky = frame.technique(atmosphere::AtmosphereSection::kKey) != nullptr;
  auto make = [&]<class Variant>() -> std::unique_ptr<shared::CpuShadingAccessors> {
    return std::make_unique<Variant>(frame, table, std::move(shadowLayers), std::move(atmosphere));
  };
  mKernel->variant = water && sky ? make.operator()<shared::KernelWaterAtmosphere>()
                     : water      ? make.operator()<shared::KernelWater>()
                     : sky        ? make.operator()<shared::KernelAtmosphere>()
                                  : make.operator()<shared::KernelPlain>();
}

CpuShading::~CpuShading() = default;

glm::vec3 CpuShading::shade(const GBufferTexel& texel, const glm::vec2& uv,
                            const CameraTransform& camera) {
  return mKernel->variant->shade(texel, uv, camera);
}

}  // namespace prism::render
