#include "imaging/image_difference.h"

#include <Eigen/Core>
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "spectral/colour_difference.h"
#include "spectral/colour_space.h"
#include "core/error.h"
#include "core/parallel_for.h"

namespace prism::imaging {
namespace {

struct PixelForms {
  Eigen::Vector3d xyz;     // relative to white Y = 1
  Eigen::Vector3d linear;  // linear sRGB, white = 1
  std::array<int, 3> srgb8;
};

// One input's pixels in the three forms of image_difference.h.
class PixelReader {
 public:
  explicit PixelReader(const DifferenceInput& input)
      : mInput(input),
        mSrgb(colourSpace("srgb")),
        mDisplay(input.srgb8 ? colourSpace(input.srgb8->colourSpace()) : mSrgb) {
    PRISM_CHECK((input.srgb8 == nullptr) != (input.linear == nullptr));
    if (input.srgb8) {
      // 256 entries through the exact decode of the image's transfer.
      for (int v = 0; v < 256; ++v) mDecode[v] = mDisplay.decode(Eigen::Vector3d::Constant(v / 255.0)).x();
      return;
    }
    const bool camera = input.colour == ColourMeaning::CameraRgb && input.cameraToXyz;
    if (input.colour != ColourMeaning::LinearSrgb && input.colour != ColourMeaning::Xyz && !camera)
      throw Error("cannot compare a " + std::string(colourMeaningName(input.colour)) +
                  " image: only linear-srgb, xyz and a camera's RGB with its matrix have a colorimetric meaning here");
    if (input.linear->channels < 3) throw Error("cannot compare a 1-channel image as colour");
    // A caller's image whose pixels do not fill it was read past its end (a mean of 100, no error).
    const FloatImage& image = *input.linear;
    if (image.width < 0 || image.height < 0 ||
        image.pixels.size() != static_cast<std::size_t>(image.width) * static_cast<std::size_t>(image.height) *
                                   static_cast<std::size_t>(image.channels))
      throw Error("cannot compare a " + std::to_string(image.width) + " × " + std::to_string(image.height) + " × " +
                  std::to_string(image.channels) + " image holding " + std::to_string(image.pixels.size()) + " values");
    if (!(input.whiteLuminance > 0.0))
      throw Error("white luminance must be positive, not " + std::to_string(input.whiteLuminance));
  }

  int width() const { return mInput.srgb8 ? mInput.srgb8->width() : mInput.linear->width; }
  int height() const { return mInput.srgb8 ? mInput.srgb8->height() : mInput.linear->height; }

  PixelForms at(int x, int y) const {
    PixelForms p;
    if (mInput.srgb8) {
      Rgb8 v = mInput.srgb8->pixel(x, y);
      const Eigen::Vector3d decoded(mDecode[v.r], mDecode[v.g], mDecode[v.b]);
      if (&mDisplay == &mSrgb) {
        p.srgb8 = {v.r, v.g, v.b};
        p.linear = decoded;
        p.xyz = mSrgb.rgbToXyz * p.linear;
        return p;
      }
      p.xyz = mDisplay.rgbToXyz * decoded;
      p.linear = mSrgb.xyzToRgb * p.xyz;
    } else {
      fromLinear(p, x, y);
    }
    Eigen::Vector3d encoded = mSrgb.encode(p.linear.cwiseMax(0.0).cwiseMin(1.0));
    for (int c = 0; c < 3; ++c) p.srgb8[c] = static_cast<int>(std::lround(encoded[c] * 255.0));
    return p;
  }

 private:
  // A linear input's pixel, in XYZ and linear sRGB relative to white.
  void fromLinear(PixelForms& p, int x, int y) const {
    const FloatImage& image = *mInput.linear;
    Eigen::Vector3d value(image.at(x, y, 0), image.at(x, y, 1), image.at(x, y, 2));
    value /= mInput.whiteLuminance;
    if (mInput.colour == ColourMeaning::Xyz || mInput.colour == ColourMeaning::CameraRgb) {
      p.xyz = mInput.colour == ColourMeaning::Xyz ? value : Eigen::Vector3d(*mInput.cameraToXyz * value);
      p.linear = mSrgb.xyzToRgb * p.xyz;
    } else {
      p.linear = value;
      p.xyz = mSrgb.rgbToXyz * value;
    }
  }

  const DifferenceInput& mInput;
  const RgbColourSpace& mSrgb;
  const RgbColourSpace& mDisplay;  // an 8-bit input's space
  std::array<double, 256> mDecode{};
};

std::string sizeText(const PixelReader& r) {
  return std::to_string(r.width()) + " × " + std::to_string(r.height());
}

}  // namespace

double percentileOfSorted(std::span<const float> sorted, double p) {
  PRISM_CHECK(!sorted.empty() && p >= 0.0 && p <= 1.0);
  double rank = p * static_cast<double>(sorted.size() - 1);
  std::size_t lo = static_cast<std::size_t>(std::floor(rank));
  std::size_t hi = std::min(lo + 1, sorted.size() - 1);
  double fraction = rank - static_cast<double>(lo);
  // Equal neighbours (both +∞ included) or an exact rank need no interpolation.
  if (fraction == 0.0 || sorted[lo] == sorted[hi]) return sorted[lo];
  return sorted[lo] + fraction * (static_cast<double>(sorted[hi]) - sorted[lo]);
}

DifferenceStats deltaEStats(std::span<const float> deltaE, double thresholdDeltaE) {
  DifferenceStats s;
  s.thresholdDeltaE = thresholdDeltaE;
  s.pixelCount = deltaE.size();
  if (deltaE.empty()) return s;
  constexpr float kInf = std::numeric_limits<float>::infinity();
  std::vector<float> sorted(deltaE.begin(), deltaE.end());
  for (float& v : sorted)
    if (!std::isfinite(v)) v = kInf;
  std::sort(sorted.begin(), sorted.end());
  double sum = 0.0;
  std::size_t above = 0;
  for (float v : sorted) {
    sum += v;
    above += v > thresholdDeltaE;
  }
  const double n = static_cast<double>(sorted.size());
  s.meanDeltaE = sum / n;
  s.medianDeltaE = percentileOfSorted(sorted, 0.5);
  s.p95DeltaE = percentileOfSorted(sorted, 0.95);
  s.p99DeltaE = percentileOfSorted(sorted, 0.99);
  s.maxDeltaE = sorted.back();
  s.fractionAbove = static_cast<double>(above) / n;
  return s;
}

ImageDifference compareImages(const DifferenceInput& reference, const DifferenceInput& test,
                              const DifferenceOptions& options) {
  const PixelReader a(reference), b(test);
  if (a.width() != b.width() || a.height() != b.height())
    throw Error("images differ in size: reference " + sizeText(a) + ", test " + sizeText(b));
  const int width = a.width(), height = a.height();
  const Eigen::Vector3d whiteXyz = colourSpace("srgb").whiteXyz();

  FloatImage map(width, height, 1);
  // Per-row sums, added in row order afterwards, so the result does not depend on threads.
  std::vector<double> rowMae(static_cast<std::size_t>(height)), rowRelative(static_cast<std::size_t>(height));
  parallelFor(static_cast<std::size_t>(height), options.threads, [&](std::size_t row) {
    const int y = static_cast<int>(row);
    double mae = 0.0, relative = 0.0;
    for (int x = 0; x < width; ++x) {
      PixelForms pa = a.at(x, y), pb = b.at(x, y);
      map.at(x, y, 0) = static_cast<float>(
          deltaE(xyzToLab(pa.xyz, whiteXyz), xyzToLab(pb.xyz, whiteXyz), DeltaEFormula::Ciede2000));
      for (int c = 0; c < 3; ++c) {
        mae += std::abs(pa.srgb8[c] - pb.srgb8[c]);
        relative +=
            std::abs(pa.linear[c] - pb.linear[c]) / std::max(std::abs(pa.linear[c]), options.relativeEpsilon);
      }
    }
    rowMae[row] = mae;
    rowRelative[row] = relative;
  });

  ImageDifference out;
  out.stats = deltaEStats(map.pixels, options.thresholdDeltaE);
  const double samples = 3.0 * static_cast<double>(map.pixelCount());
  if (samples > 0.0) {
    double mae = 0.0, relative = 0.0;
    for (std::size_t row = 0; row < rowMae.size(); ++row) {
      mae += rowMae[row];
      relative += rowRelative[row];
    }
    out.stats.mae8 = mae / samples;
    out.stats.relativeError = relative / samples;
  }
  if (options.keepMap) out.deltaEMap = std::move(map);
  return out;
}

}  // namespace prism::imaging
