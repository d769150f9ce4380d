// The CPU twin's side of the nebula (techniques/technique_cpu_twin.h): the accessors that
// shaders/common_nebula_lighting.glsl defines on the GPU, over the optical depth the nebula's
// pass read back and the star depths it marched with (NebulaTexels) and over the section's block
// of star lights, and shared/nebula_lighting.glsl compiled as C++.
#pragma once

#include <cstddef>
#include <memory>
#include <string_view>
#include <vector>

#include "techniques/nebula/nebula_layout.h"
#include "techniques/nebula/nebula_precomputed.h"
#include "techniques/nebula/nebula_section.h"
#include "techniques/technique_cpu_twin.h"

namespace prism::nebula {

// The optical depth (µm) from the camera to each pixel's surface, width × height, row 0 at the
// bottom (GL's order): what the lighting pass reads of the nebula (NebulaPass::readTexels).
// The star depths are the precomputation's the pass marched with (its stars in the section's order).
struct NebulaTexels final : TechniqueTexels {
  int width = 0, height = 0;
  std::vector<float> opticalDepthUm;
  std::shared_ptr<const NebulaRenderer> precomputation;
};

}  // namespace prism::nebula

namespace prism::shared {

class NebulaCpuTwin {
 public:
  static constexpr std::string_view kKey = nebula::NebulaSection::kKey;
  // Without texels (no pass ran), nothing dims and no star lights a surface.
  explicit NebulaCpuTwin(const TechniqueTwinInput& input)
      : mTexels(dynamic_cast<const nebula::NebulaTexels*>(input.texels)), mBlock(input.block) {}

 protected:
  float nebulaOpticalDepthAt(vec2 uv) const {
    if (!mTexels || mTexels->width == 0) return 0.0f;
    const int x = static_cast<int>(uv.x * static_cast<float>(mTexels->width));
    const int y = static_cast<int>(uv.y * static_cast<float>(mTexels->height));
    return mTexels->opticalDepthUm[static_cast<std::size_t>(y * mTexels->width + x)];
  }
  NebulaLightConstants frameNebula() const {
    if (!mTexels || !mTexels->precomputation) return NebulaLightConstants{vec4(0.0f, 0.0f, 0.0f, 1.0f), 0, 0, 0, 0};
    return mBlock.constantsAs<NebulaLightConstants>();
  }
  vec4 nebulaStarData(int i) const { return mBlock.dataAt<vec4>(static_cast<std::size_t>(i)); }
  float nebulaStarDepthAt(int star, vec3 pCube) const {
    const auto& depths = mTexels->precomputation->precomputed().starDepth;
    PRISM_CHECK(static_cast<std::size_t>(star) < depths.size());
    float depth = 0.0f;
    depths[static_cast<std::size_t>(star)].sample(glm::dvec3(pCube), &depth);
    return depth;
  }

 private:
  const nebula::NebulaTexels* mTexels;
  const TechniqueBlock& mBlock;
};

}  // namespace prism::shared
