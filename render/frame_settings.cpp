#include "render/frame_settings.h"

#include <cmath>

#include <fmt/format.h>

#include "core/error.h"
#include "scene/scene.h"
#include "spectral/illuminant.h"
#include "spectral/observer.h"

namespace prism::render {

std::string_view renderModeName(RenderMode mode) {
  switch (mode) {
    case RenderMode::Rgb: return "rgb";
    case RenderMode::Naive: return "naive";
    case RenderMode::JakobHanika: return "jakob-hanika";
    case RenderMode::Reference: return "reference";
    case RenderMode::Optimised4: return "optimised4";
  }
  return "?";
}

std::string_view toneMapName(ToneMap toneMap) {
  switch (toneMap) {
    case ToneMap::None: return "none";
    case ToneMap::Reinhard: return "reinhard";
    case ToneMap::Aces: return "aces";
  }
  return "?";
}

std::string_view upsamplingLookupName(UpsamplingLookup lookup) {
  return lookup == UpsamplingLookup::Manual ? "manual" : "filtered";
}

std::string_view gbufferAlbedoName(GBufferAlbedo albedo) {
  return albedo == GBufferAlbedo::Rgb ? "rgb" : "coefficients";
}

void validate(const FrameSettings& settings) {
  if (settings.width < 1 || settings.height < 1 || settings.width > 16384 ||
      settings.height > 16384) {
    throw Error(fmt::format("image size {}x{} must be within 1..16384 on each side",
                            settings.width, settings.height));
  }
  validate(settings.sampling);
  // RGB mode carries colours, not spectra, and its colour spaces are defined on CIE 1931: another
  // observer's curves have nothing to weigh there, and the image came out under CIE 1931, the
  // camera or CIE 1964 ignored without a word.
  if (settings.mode == RenderMode::Rgb && settings.observer != "cie1931") {
    if (observer(settings.observer).isCamera)
      throw Error(fmt::format("mode rgb cannot show the camera \"{}\": its curves weigh spectra (choose a spectral mode, "
                              "or the observer cie1931)", settings.observer));
    throw Error(fmt::format("mode rgb renders under CIE 1931, whose curves its colour spaces are defined with: the observer "
                            "{} needs a spectral mode", settings.observer));
  }
  // The sky's four wavelengths and their weights are fitted for CIE 1931's curves: under a camera's
  // they came out green (ΔE00 12–14 from the reference), under CIE 1964 at two to three times the error.
  if (settings.mode == RenderMode::Optimised4 && settings.observer != "cie1931")
    throw Error(fmt::format("mode optimised4's four wavelengths and weights are fitted for CIE 1931: the observer {} "
                            "needs a spectral mode (jakob-hanika or reference)", settings.observer));
  if (settings.shadowMapSize < 16 || settings.shadowMapSize > 8192) {
    throw Error(fmt::format("shadow map size {} must be within 16..8192", settings.shadowMapSize));
  }
  if (settings.shadowCascades < 1 || settings.shadowCascades > kShadowCascadesMax) {
    throw Error(fmt::format("shadow cascades {} must be within 1..{}", settings.shadowCascades, kShadowCascadesMax));
  }
  validate(settings.display);
}

void validateEv100(float ev100) {
  if (!(std::abs(ev100) <= kEv100Limit)) {
    throw Error(fmt::format("exposure (EV100) {} must be within ±{:g}", ev100, kEv100Limit));
  }
}

void validate(const DisplaySettings& settings) {
  if (settings.whiteBalance != "none") lampSpectrum(settings.whiteBalance);  // Error when unknown
  if (settings.ev100) validateEv100(*settings.ev100);
  if (settings.colourSpace != "srgb" && settings.colourSpace != "display-p3" &&
      settings.colourSpace != "p3" && settings.colourSpace != "rec2020") {
    throw Error(fmt::format("unknown display \"{}\" (srgb, display-p3, rec2020)",
                            settings.colourSpace));
  }
}

SamplingSettings effectiveSampling(const FrameSettings& settings) {
  if (settings.mode == RenderMode::Rgb || settings.mode == RenderMode::Optimised4) {
    SamplingSettings unused = settings.sampling;  // neither mode samples: nothing to build or fit
    unused.strategy = SamplingStrategy::Uniform;
    return unused;
  }
  if (settings.mode != RenderMode::Reference) return settings.sampling;
  SamplingSettings reference;
  reference.count = kReferenceWavelengths;
  reference.minNm = kLambdaMinNm;
  reference.maxNm = kLambdaMaxNm;
  reference.strategy = SamplingStrategy::Uniform;
  return reference;
}

bool usesSampling(RenderMode mode) { return mode == RenderMode::Naive || mode == RenderMode::JakobHanika; }

bool framesDiffer(const FrameSettings& settings) {
  SamplingStrategy strategy = effectiveSampling(settings).strategy;
  return strategy != SamplingStrategy::Uniform && strategy != SamplingStrategy::Optimised;
}

}  // namespace prism::render
