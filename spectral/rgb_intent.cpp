#include "spectral/rgb_intent.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <Eigen/Core>

#include "core/error.h"
#include "shared_cpp.h"
#include "spectral/observer.h"
#include "spectral/sigmoid_fit.h"

namespace prism::shared {
#include "sigmoid.glsl"
}  // namespace prism::shared

namespace prism {
namespace {

// pbrt-v4's rule for an unbounded colour: its usable channels (negative, NaN and infinite read
// as 0) and their scale (sigmoid.glsl's unboundedScale), capped at the largest float so that a huge channel stays finite.
struct UnboundedSplit {
  glm::vec3 rgb;
  float scale;
};

UnboundedSplit unboundedSplit(const glm::vec3& rgb) {
  glm::vec3 c;
  for (int i = 0; i < 3; ++i) c[i] = std::isfinite(rgb[i]) ? std::max(rgb[i], 0.0f) : 0.0f;
  return {c, std::min(shared::unboundedScale(c), std::numeric_limits<float>::max())};
}

}  // namespace

RgbAlbedoSpectrum::RgbAlbedoSpectrum(const RgbToSpectrumTable& table, const glm::vec3& rgb)
    : mCoeffs(table.lookup(rgb)) {}

Spectrum RgbAlbedoSpectrum::toDense() const { return upsampledReflectanceSpectrum(mCoeffs); }

RgbUnboundedSpectrum::RgbUnboundedSpectrum(const RgbToSpectrumTable& table, const glm::vec3& rgb) {
  UnboundedSplit s = unboundedSplit(rgb);
  mCoeffs = table.lookup(s.scale > 0.0f ? s.rgb / s.scale : glm::vec3(0.0f));
  mScale = s.scale;
}

RgbUnboundedSpectrum RgbUnboundedSpectrum::fitted(const RgbColourSpace& space, const glm::vec3& rgb) {
  UnboundedSplit s = unboundedSplit(rgb);
  // The fitter works in double, so the albedo is divided in double too.
  Eigen::Vector3d albedo = Eigen::Vector3d::Zero();
  if (s.scale > 0.0f) albedo = Eigen::Vector3d(s.rgb.r, s.rgb.g, s.rgb.b) / static_cast<double>(s.scale);
  SigmoidFitter fitter(space, gamutWhiteIlluminant(space), cie1931Observer());
  return {fitter.fit(albedo).coeffs, s.scale};
}

float RgbUnboundedSpectrum::at(float lambdaNm) const {
  return shared::upsampledReflectance(mCoeffs, lambdaNm) * mScale;
}

Spectrum RgbUnboundedSpectrum::toDense() const {
  return upsampledReflectanceSpectrum(mCoeffs) * static_cast<double>(mScale);
}

Spectrum scaledWhiteIlluminant(const RgbColourSpace& space, double luminance) {
  Spectrum white = gamutWhiteIlluminant(space);
  return white * (luminance / luminousIntegral(white));
}

RgbIlluminantSpectrum::RgbIlluminantSpectrum(const RgbColourSpace& space, const RgbUnboundedSpectrum& unbounded,
                                             double whiteLuminance)
    : mWhite(scaledWhiteIlluminant(space, whiteLuminance)), mUnbounded(unbounded) {}

RgbIlluminantSpectrum::RgbIlluminantSpectrum(const RgbToSpectrumTable& table, const RgbColourSpace& space,
                                             const glm::vec3& rgb, double whiteLuminance)
    : RgbIlluminantSpectrum(space, RgbUnboundedSpectrum(table, rgb), whiteLuminance) {
  PRISM_CHECK(table.gamut() == space.name);
}

RgbIlluminantSpectrum RgbIlluminantSpectrum::fitted(const RgbColourSpace& space, const glm::vec3& rgb,
                                                    double whiteLuminance) {
  return {space, RgbUnboundedSpectrum::fitted(space, rgb), whiteLuminance};
}

double RgbIlluminantSpectrum::at(double lambdaNm) const {
  return mWhite.at(lambdaNm) * static_cast<double>(mUnbounded.at(static_cast<float>(lambdaNm)));
}

Spectrum RgbIlluminantSpectrum::toDense() const { return mWhite * mUnbounded.toDense(); }

}  // namespace prism
