// The CPU twin's side of the nebula (techniques/technique_cpu_twin.h): the accessor that
// shaders/common_nebula_lighting.glsl defines on the GPU, over the optical depth the nebula's
// pass read back (NebulaTexels), and shared/nebula_lighting.glsl compiled as C++.
#pragma once

#include <cstddef>
#include <string_view>
#include <vector>

#include "shared_cpp.h"
#include "techniques/nebula/nebula_section.h"
#include "techniques/technique_cpu_twin.h"

namespace prism::shared {
#include "nebula_lighting.glsl"
}  // namespace prism::shared

namespace prism::nebula {

// The optical depth (µm) from the camera to each pixel's surface, width × height, row 0 at the
// bottom (GL's order): what the lighting pass reads of the nebula (NebulaPass::readTexels).
struct NebulaTexels final : TechniqueTexels {
  int width = 0, height = 0;
  std::vector<float> opticalDepthUm;
};

}  // namespace prism::nebula

namespace prism::shared {

class NebulaCpuTwin {
 public:
  static constexpr std::string_view kKey = nebula::NebulaSection::kKey;
  // Without texels (no pass ran), nothing dims.
  explicit NebulaCpuTwin(const TechniqueTwinInput& input)
      : mTexels(dynamic_cast<const nebula::NebulaTexels*>(input.texels)) {}

 protected:
  float nebulaOpticalDepthAt(vec2 uv) const {
    if (!mTexels || mTexels->width == 0) return 0.0f;
    const int x = static_cast<int>(uv.x * static_cast<float>(mTexels->width));
    const int y = static_cast<int>(uv.y * static_cast<float>(mTexels->height));
    return mTexels->opticalDepthUm[static_cast<std::size_t>(y * mTexels->width + x)];
  }

 private:
  const nebula::NebulaTexels* mTexels;
};

}  // namespace prism::shared
