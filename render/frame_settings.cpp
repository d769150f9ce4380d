#include "render/frame_settings.h"

#include <cmath>

#include <fmt/format.h>

#include "core/error.h"
#include "spectral/illuminant.h"
#include "spectral/observer.h"

namespace prism::render {

RenderMode renderModeFromName(std::string_view name) {
  if (name == "rgb") return RenderMode::Rgb;
  if (name == "naive") return RenderMode::Naive;
  if (name == "jakob-hanika") return RenderMode::JakobHanika;
  if (name == "reference") return RenderMode::Reference;
  if (name == "optimised4") return RenderMode::Optimised4;
  throw Error(fmt::format("unknown mode \"{}\" (rgb, naive, jakob-hanika, reference, optimised4)", name));
}

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

ToneMap toneMapFromName(std::string_view name) {
  if (name == "none") return ToneMap::None;
  if (name == "reinhard") return ToneMap::Reinhard;
  if (name == "aces") return ToneMap::Aces;
  throw Error(fmt::format("unknown tone map \"{}\" (none, reinhard, aces)", name));
}

void validate(const FrameSettings& settings) {
  if (settings.width < 1 || settings.height < 1 || settings.width > 16384 ||
      settings.height > 16384) {
    throw Error(fmt::format("image size {}x{} must be within 1..16384 on each side",
                            settings.width, settings.height));
  }
  validate(settings.sampling);
  observer(settings.observer);
  if (settings.shadowMapSize < 16 || settings.shadowMapSize > 8192) {
    throw Error(fmt::format("shadow map size {} must be within 16..8192", settings.shadowMapSize));
  }
  if (settings.whiteBalance != "none") illuminant(settings.whiteBalance);  // Error when unknown
  if (settings.ev100 && !std::isfinite(*settings.ev100)) {
    throw Error("exposure (EV100) must be a finite number");
  }
  if (settings.display != "srgb" && settings.display != "display-p3" &&
      settings.display != "p3" && settings.display != "rec2020") {
    throw Error(fmt::format("unknown display \"{}\" (srgb, display-p3, rec2020)",
                            settings.display));
  }
}

SamplingSettings effectiveSampling(const FrameSettings& settings) {
  if (settings.mode != RenderMode::Reference) return settings.sampling;
  SamplingSettings reference;
  reference.count = kReferenceWavelengths;
  reference.minNm = kLambdaMinNm;
  reference.maxNm = kLambdaMaxNm;
  reference.strategy = SamplingStrategy::Uniform;
  return reference;
}

}  // namespace prism::render
