// For the render tests: the sky's tables of an AtmospherePass read back into the CPU twin's
// form (cpu_shading.h's AtmosphereTexels). Stalls; tests only.
#pragma once

#include "render/atmosphere_pass.h"
#include "render/cpu_shading.h"

namespace prism::render {

AtmosphereTexels readAtmosphereTexels(const AtmospherePass& pass);

}  // namespace prism::render
