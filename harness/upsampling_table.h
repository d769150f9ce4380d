// The Jakob–Hanika table a scene renders with, for the commands and experiments that render: the
// scene's colour space at the renderers' resolution (spectral/rgb_to_spectrum_cache.h), from the
// cache, or built with a progress bar on first use (~20 s for sRGB on 2 cores). Kept for the life
// of the process.
#pragma once

#include "scene/scene.h"
#include "spectral/rgb_to_spectrum_table.h"

namespace prism::harness {

const RgbToSpectrumTable& upsamplingTable(const Scene& scene);

}  // namespace prism::harness
