#include "reference/path_tracer.h"

#include <fmt/format.h>

#include "core/error.h"
#include "spectral/observer.h"

namespace prism::reference {

LightTransport lightTransportFromName(std::string_view name) {
  if (name == "direct") return LightTransport::Direct;
  if (name == "global") return LightTransport::Global;
  throw Error(fmt::format("unknown light transport \"{}\" (known: direct, global)", name));
}

PixelFilter pixelFilterFromName(std::string_view name) {
  if (name == "box") return PixelFilter::Box;
  if (name == "centre" || name == "center") return PixelFilter::Centre;
  throw Error(fmt::format("unknown pixel filter \"{}\" (known: box, centre)", name));
}

void validate(const ReferenceSettings& s) {
  if (s.width < 1 || s.height < 1 || s.width > 16384 || s.height > 16384) {
    throw Error(fmt::format("--width {} --height {}: each side of the image must be within 1–16384", s.width, s.height));
  }
  if (s.samplesPerPixel < 1 || s.samplesPerPixel > (1 << 20)) {
    throw Error(fmt::format("--spp must be within 1–1048576, got {}", s.samplesPerPixel));
  }
  if (s.maxDepth < 1 || s.maxDepth > 1024) throw Error(fmt::format("--max-depth must be within 1–1024, got {}", s.maxDepth));
  if (s.threads > 1024) throw Error(fmt::format("--threads must be at most 1024 (0: all cores), got {}", s.threads));
  if (s.wavelengths.count != 4) {
    throw Error(fmt::format("the reference traces 4 hero wavelengths per path, got {}", s.wavelengths.count));
  }
  if (s.wavelengths.strategy == SamplingStrategy::Optimised) {
    throw Error("--strategy optimised is a fitted, biased set for real-time frames; the reference needs an "
                "unbiased one (uniform, stratified, rotated, importance or lights)");
  }
  prism::validate(s.wavelengths);
  observer(s.observer);  // throws naming it when unknown
}

void validate(const ReferenceRegion& r, const ReferenceSettings& s) {
  if (r.rowBegin < 0 || r.rowBegin >= r.rowEnd || r.rowEnd > s.height) {
    throw Error(fmt::format("rows {}:{} are not a range of the image's {}", r.rowBegin, r.rowEnd, s.height));
  }
  if (r.sampleBegin < 0 || r.sampleBegin >= r.sampleEnd || r.sampleEnd > s.samplesPerPixel) {
    throw Error(fmt::format("--samples {}:{} is not a range of the {} paths per pixel (0 ≤ A < B ≤ {})",
                            r.sampleBegin, r.sampleEnd, s.samplesPerPixel, s.samplesPerPixel));
  }
}

}  // namespace prism::reference
