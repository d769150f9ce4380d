#include "harness/upsampling_table.h"

#include "harness/progress_bar.h"
#include "spectral/rgb_to_spectrum_cache.h"

namespace prism::harness {

const RgbToSpectrumTable& upsamplingTable(const Scene& scene) {
  ProgressBar bar("upsampling table for " + scene.colourSpace);
  return rendererRgbToSpectrumTable(scene.colourSpace,
                                    [&](std::size_t done, std::size_t total) { bar.update(done, total); });
}

}  // namespace prism::harness
