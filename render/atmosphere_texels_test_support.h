// For the render tests: the sky's tables of an atmosphere::AtmospherePass read back into the CPU twin's
// form (cpu_shading.h's AtmosphereTexels). Stalls; tests only.
#pragma once

#include "techniques/atmosphere/gpu/atmosphere_pass.h"
#include "render/cpu_shading.h"

namespace prism::render {

AtmosphereTexels readAtmosphereTexels(const atmosphere::AtmospherePass& pass);

}  // namespace prism::render
