#include "app/upsampling_table.h"

#include "app/progress_bar.h"
#include "spectral/rgb_to_spectrum_cache.h"

namespace prism::app {

RgbToSpectrumTable upsamplingTable(const std::string& colourSpace) {
  ProgressBar bar("upsampling table for " + colourSpace);
  return cachedRgbToSpectrumTable(colourSpace, 64,
                                  [&](std::size_t done, std::size_t total) { bar.update(done, total); });
}

}  // namespace prism::app
