// The Jakob–Hanika table of a colour space for the commands that render: from the cache, or
// built with a progress bar on first use (~20 s for sRGB on 2 cores).
#pragma once

#include <string>

#include "spectral/rgb_to_spectrum_table.h"

namespace prism::harness {

RgbToSpectrumTable upsamplingTable(const std::string& colourSpace);

}  // namespace prism::harness
