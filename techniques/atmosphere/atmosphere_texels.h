// The sky's tables as its GPU pass holds them (techniques/atmosphere/gpu/atmosphere_pass.h, read
// back), for the CPU twin (atmosphere_cpu_twin.h): one entry per texture-array layer, texels row
// by row from the bottom (the aerial-perspective volume's rows hold every batch side by side).
#pragma once

#include <vector>

#include <glm/glm.hpp>

#include "techniques/technique_cpu_twin.h"

namespace prism::atmosphere {

struct AtmosphereTexels final : TechniqueTexels {
  std::vector<std::vector<glm::vec4>> transmittance, multipleScattering, skyView, aerialPerspective;
  std::vector<glm::vec4> skyIrradiance;  // four per batch
};

}  // namespace prism::atmosphere
