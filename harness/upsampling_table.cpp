#include "harness/upsampling_table.h"

#include "harness/progress_bar.h"
#include "spectral/rgb_to_spectrum_cache.h"

namespace prism::harness {

RgbToSpectrumTable upsamplingTable(const std::string& colourSpace) {
  ProgressBar bar("upsampling table for " + colourSpace);
  return cachedRgbToSpectrumTable(colourSpace, 64,
                                  [&](std::size_t done, std::size_t total) { bar.update(done, total); });
}

}  // namespace prism::harness
