// The CPU twin's side of the water (techniques/technique_cpu_twin.h): the accessors that
// shaders/common_water_lighting.glsl defines on the GPU, over the frame's water block.
#pragma once

#include <cstddef>
#include <string_view>

#include "techniques/technique_cpu_twin.h"
#include "techniques/underwater/underwater_layout.h"
#include "techniques/underwater/water_section.h"

namespace prism::shared {

class WaterCpuTwin {
 public:
  static constexpr std::string_view kKey = underwater::WaterSection::kKey;
  explicit WaterCpuTwin(const TechniqueTwinInput& input) : mBlock(input.block) {}

 protected:
  WaterConstants frameWater() const { return mBlock.constantsAs<WaterConstants>(); }
  vec4 frameWaterSpectrum(int b, int j) const {
    return mBlock.dataAt<vec4>(static_cast<std::size_t>(waterSpectrumIndex(b, j)));
  }

 private:
  const TechniqueBlock& mBlock;
};

}  // namespace prism::shared
