// The CPU twin's side of the sky (techniques/technique_cpu_twin.h): the accessors that
// shaders/common_sky_lighting.glsl defines on the GPU, over the frame's sky block and the sky's
// tables read back from its pass, and atmosphere_luts.glsl and atmosphere_lighting.glsl compiled
// over them.
#pragma once

#include <cstddef>
#include <string_view>
#include <vector>

#include "core/error.h"
#include "techniques/atmosphere/atmosphere_layout.h"
#include "techniques/atmosphere/atmosphere_section.h"
#include "techniques/atmosphere/atmosphere_texels.h"
#include "techniques/technique_cpu_twin.h"

namespace prism::shared {

class AtmosphereCpuTwin {
 public:
  static constexpr std::string_view kKey = atmosphere::AtmosphereSection::kKey;
  explicit AtmosphereCpuTwin(const TechniqueTwinInput& input)
      : mBlock(input.block),
        mTexels(dynamic_cast<const atmosphere::AtmosphereTexels*>(input.texels)),
        mBatchCount(input.batchCount) {
    PRISM_CHECK(mTexels != nullptr);
  }

 protected:
  SkyConstants frameSky() const { return mBlock.constantsAs<SkyConstants>(); }
  GpuAtmosphere frameAtmosphere(int b) const { return mBlock.dataAt<GpuAtmosphere>(index(b)); }
  vec4 transmittanceLutTexel(int b, int x, int y) const {
    return texel(mTexels->transmittance, b, x, y, kTransmittanceLutWidth);
  }
  vec4 multipleScatteringLutTexel(int b, int x, int y) const {
    return texel(mTexels->multipleScattering, b, x, y, kMultipleScatteringLutSize);
  }
  vec4 skyViewLutTexel(int b, int x, int y) const { return texel(mTexels->skyView, b, x, y, kSkyViewLutWidth); }
  vec4 aerialPerspectiveTexel(int b, int x, int y, int slice, int j) const {
    return texel(mTexels->aerialPerspective, j * kAerialPerspectiveSlices + slice, b * kAerialPerspectiveSize + x, y,
                 kAerialPerspectiveSize * mBatchCount);
  }
  vec4 skyIrradianceCoefficient(int b, int k) const { return mTexels->skyIrradiance[index(b * 4 + k)]; }

#include "atmosphere_luts.glsl"
#include "atmosphere_lighting.glsl"

 private:
  static std::size_t index(int i) { return static_cast<std::size_t>(i); }
  static vec4 texel(const std::vector<std::vector<glm::vec4>>& layers, int layer, int x, int y, int width) {
    return layers[index(layer)][index(y * width + x)];
  }

  const TechniqueBlock& mBlock;
  const atmosphere::AtmosphereTexels* mTexels;
  int mBatchCount;
};

}  // namespace prism::shared
