#include "render/cpu_shading.h"

#include <algorithm>
#include <iterator>
#include <string_view>
#include <utility>

#include "core/error.h"

namespace prism::shared {

// What the CPU twin is made from (CpuShading's constructor).
struct CpuShadingInputs {
  render::FrameData frame;
  const RgbToSpectrumTable& table;
  std::vector<std::vector<float>> shadowLayers;
  TechniqueTexelsByKey texels;
};

// The accessors pixel_shading.glsl reads of the frame, over the same FrameData the GPU reads;
// each variant adds its techniques' twins (techniques/technique_cpu_twin.h).
class CpuShadingCore {
 public:
  explicit CpuShadingCore(CpuShadingInputs inputs) : mIn(std::move(inputs)) {}
  virtual ~CpuShadingCore() = default;
  virtual vec3 shade(const render::GBufferTexel& texel, vec2 uv, const CameraTransform& camera) = 0;

 protected:
  static std::size_t index(int i) { return static_cast<std::size_t>(i); }
  GpuBatch frameBatch(int b) const { return mIn.frame.batches[index(b)]; }
  GpuLight frameLight(int l) const { return mIn.frame.lights[index(l)]; }
  GpuMaterial frameMaterial(int id) const { return mIn.frame.materials[index(id)]; }
  vec4 frameLightSpectrum(int l, int b) const {
    return mIn.frame.lightSpectra[index(lightSpectrumIndex(l, b, mIn.frame.constants.batchCount))];
  }
  vec4 frameMaterialSpectrum(int s, int b, int j) const {
    return mIn.frame.materialSpectra[index(materialSpectrumIndex(s, b, j, mIn.frame.constants.batchCount))];
  }
  float shadowDepthAt(int layer, int x, int y) const {
    return mIn.shadowLayers[index(layer)][index(y * mIn.frame.constants.shadowMapSize + x)];
  }
  vec3 upsamplingCoefficients(vec3 rgb) const {
    return mIn.frame.constants.gbufferCoefficients != 0 ? mTexelCoefficients : mIn.table.lookup(rgb);
  }
  vec3 emissionCoefficients(vec3 rgb) const { return mIn.table.lookup(rgb); }
  // What the twin of the technique `key` is made from.
  TechniqueTwinInput twinInput(std::string_view key) const {
    auto texels = mIn.texels.find(key);
    return {*mIn.frame.technique(key), texels == mIn.texels.end() ? nullptr : texels->second.get(),
            mIn.frame.constants.batchCount};
  }

  CpuShadingInputs mIn;
  vec3 mTexelCoefficients{0.0f};  // of the texel being shaded
};

}  // namespace prism::shared

// Each variant's body before pixel_shading.glsl (cmake/PrismCpuTwins.cmake), as lighting.frag's.
#define PRISM_CPU_SHADING_SHADE                                                                   \
  vec3 shade(const render::GBufferTexel& texel, vec2 uv, const CameraTransform& camera) override { \
    if (texel.materialId == 0) {                                                                   \
      return shadeBackground(mIn.frame.constants, worldFromDepth(camera.inverseViewProjection, uv, 1.0f), \
                             camera.position, uv);                                                 \
    }                                                                                              \
    SurfaceSample s;                                                                               \
    s.position = worldFromDepth(camera.inverseViewProjection, uv, texel.depth);                    \
    s.normal = normalize(vec3(texel.normalRoughness));                                             \
    s.albedo = vec3(texel.albedoMetallic);                                                         \
    s.emission = texel.emission;                                                                   \
    s.metallic = texel.albedoMetallic.w;                                                           \
    s.roughness = texel.normalRoughness.w;                                                         \
    s.material = static_cast<int>(texel.materialId & ~kTechniqueShadedBit) - 1;                    \
    s.techniqueShaded = (texel.materialId & kTechniqueShadedBit) != 0u;                            \
    mTexelCoefficients = texel.coefficients;                                                       \
    return shadeSurface(mIn.frame.constants, s, camera.position, uv);                              \
  }
#define PRISM_RGB_EMISSION  // glTF's emission: a run-time test here, a variant on the GPU
#include "cpu_shading_variants.h"
#undef PRISM_RGB_EMISSION
#undef PRISM_CPU_SHADING_SHADE

namespace prism::render {

struct CpuShading::Kernel {
  std::unique_ptr<shared::CpuShadingCore> variant;
};

CpuShading::CpuShading(const FrameData& frame, const RgbToSpectrumTable& table,
                       std::vector<std::vector<float>> shadowLayers, TechniqueTexelsByKey texels)
    : mKernel(std::make_unique<Kernel>()) {
  // The variant whose twins are the frame's techniques: bit i for shared::kCpuTwinKeys[i].
  std::size_t mask = 0;
  for (const TechniqueBlock& block : frame.techniques) {
    const auto* twin = std::find(std::begin(shared::kCpuTwinKeys), std::end(shared::kCpuTwinKeys), block.key);
    if (twin == std::end(shared::kCpuTwinKeys)) {
      // A technique without lighting-pass hooks (PRT's) packs nothing the lighting pass reads;
      // every technique that does has a twin.
      PRISM_CHECK(block.constantsBinding < 0 && block.dataBinding < 0);
      continue;
    }
    mask |= std::size_t{1} << (twin - std::begin(shared::kCpuTwinKeys));
  }
  mKernel->variant = shared::kCpuShadingVariants[mask]({frame, table, std::move(shadowLayers), std::move(texels)});
}

CpuShading::~CpuShading() = default;

glm::vec3 CpuShading::shade(const GBufferTexel& texel, const glm::vec2& uv,
                            const CameraTransform& camera) {
  return mKernel->variant->shade(texel, uv, camera);
}

}  // namespace prism::render
