#include "scene/scene_spectra.h"

namespace prism {

RgbIlluminantSpectrum backgroundRadiance(const Scene& scene, const RgbColourSpace& space,
                                         const RgbToSpectrumTable& table) {
  return RgbIlluminantSpectrum(table, space, scene.background, scene.backgroundLuminance);
}

}  // namespace prism
