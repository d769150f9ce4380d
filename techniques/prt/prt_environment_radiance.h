// A PRT section's environment as radiance per direction and wavelength, before any projection:
// the distant light the reference path tracer traces PRT scenes under (TechniqueEnvironment),
// so that the bake and the SH-5 band limit are checked against light that has none. The same
// functions that sectionEnvironment (prt_section.h) projects: the CIE illuminant uniform or as
// the overcast sky's gradient over its grey ground, or the equirectangular map's texel (nearest;
// each texel upsampled with the unbounded RGB intent), scaled to the section's luminance and
// turned by its rotation, in the scene's y-up world (PRT's zenith +z is the world's +y).
#pragma once

#include <memory>

#include "spectral/rgb_to_spectrum_table.h"
#include "techniques/prt/prt_section.h"
#include "techniques/technique_section.h"

namespace prism::prt {

std::shared_ptr<const TechniqueEnvironment> environmentRadiance(const PrtSection& section, const RgbToSpectrumTable& table);

}  // namespace prism::prt
