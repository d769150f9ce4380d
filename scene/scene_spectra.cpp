#include "scene/scene_spectra.h"

#include "shared_cpp.h"
#include "spectral/colour_space.h"
#include "spectral/observer.h"
#include "spectral/sigmoid_fit.h"

namespace prism::shared {
#include "sigmoid.glsl"
}  // namespace prism::shared

namespace prism {

BackgroundRadiance::BackgroundRadiance(const Scene& scene, const RgbToSpectrumTable& table)
    : mWhite(gamutWhiteIlluminant(colourSpace(scene.colourSpace))),
      mUpsampling(lookupUnbounded(table, scene.background)) {
  mWhite *= scene.backgroundLuminance /
            (absoluteTristimulusScale(cie1931Observer()) * cie1931Observer().integrate(mWhite).y());
}

double BackgroundRadiance::at(double lambdaNm) const {
  double r = shared::upsampledReflectance(mUpsampling.coeffs, static_cast<float>(lambdaNm)) *
             mUpsampling.scale;
  return mWhite.at(lambdaNm) * r;
}

}  // namespace prism
