#include "spectral/colour_space.h"

#include <cmath>
#include <string>

#include <Eigen/LU>

#include "shared_cpp.h"
#include "core/error.h"

namespace prism::shared {
#include "transfer.glsl"
}

namespace prism {
namespace {

constexpr Chromaticity kD65{0.3127, 0.3290};      // IEC 61966-2-1, ITU-R BT.709/2020
constexpr Chromaticity kAcesWhite{0.32168, 0.33767};  // SMPTE ST 2065-1

std::vector<RgbColourSpace> makeSpaces() {
  return {
      RgbColourSpace::fromPrimaries("srgb", {0.64, 0.33}, {0.30, 0.60}, {0.15, 0.06}, kD65,
                                    Transfer::Srgb),
      RgbColourSpace::fromPrimaries("display-p3", {0.680, 0.320}, {0.265, 0.690}, {0.150, 0.060},
                                    kD65, Transfer::Srgb),
      RgbColourSpace::fromPrimaries("rec2020", {0.708, 0.292}, {0.170, 0.797}, {0.131, 0.046}, kD65,
                                    Transfer::Bt2020),
      RgbColourSpace::fromPrimaries("acescg", {0.713, 0.293}, {0.165, 0.830}, {0.128, 0.044},
                                    kAcesWhite, Transfer::Linear),
      RgbColourSpace::fromPrimaries("aces2065-1", {0.7347, 0.2653}, {0.0, 1.0}, {0.0001, -0.0770},
                                    kAcesWhite, Transfer::Linear),
  };
}

const std::vector<RgbColourSpace>& spaces() {
  static const std::vector<RgbColourSpace> instance = makeSpaces();
  return instance;
}

// Cone-response matrices (XYZ → LMS), as published.
Eigen::Matrix3d coneMatrix(Adaptation method) {
  Eigen::Matrix3d m;
  switch (method) {
    case Adaptation::Bradford:  // Lam 1985; Lindbloom's and ICC's form
      m << 0.8951, 0.2664, -0.1614, -0.7502, 1.7135, 0.0367, 0.0389, -0.0685, 1.0296;
      break;
    case Adaptation::Cat02:  // CIE 159:2004 (CIECAM02) M_CAT02
      m << 0.7328, 0.4296, -0.1624, -0.7036, 1.6975, 0.0061, 0.0030, 0.0136, 0.9834;
      break;
    case Adaptation::VonKries:  // Hunt–Pointer–Estévez, normalised to D65
      m << 0.4002400, 0.7076000, -0.0808100, -0.2263000, 1.1653200, 0.0457000, 0.0, 0.0, 0.9182200;
      break;
  }
  return m;
}

}  // namespace

Eigen::Vector3d xyToXyz(Chromaticity xy, double luminanceY) {
  return {xy.x / xy.y * luminanceY, luminanceY, (1.0 - xy.x - xy.y) / xy.y * luminanceY};
}

Chromaticity xyzToXy(const Eigen::Vector3d& xyz) {
  double sum = xyz.sum();
  return {xyz.x() / sum, xyz.y() / sum};
}

RgbColourSpace RgbColourSpace::fromPrimaries(std::string name, Chromaticity red, Chromaticity green,
                                             Chromaticity blue, Chromaticity white,
                                             Transfer transfer) {
  RgbColourSpace space{std::move(name), red, green, blue, white, transfer, {}, {}};
  // A library caller's primaries may be any numbers: degenerate ones gave a NaN matrix silently.
  for (const Chromaticity& c : {red, green, blue, white})
    if (!std::isfinite(c.x) || !std::isfinite(c.y) || c.y == 0.0)
      throw Error("colour space " + space.name + ": a primary's or the white's chromaticity is not finite or has y 0");
  if (!(white.y > 0.0)) throw Error("colour space " + space.name + ": its white's y must be above 0");
  Eigen::Matrix3d primaries;
  primaries.col(0) = xyToXyz(red);
  primaries.col(1) = xyToXyz(green);
  primaries.col(2) = xyToXyz(blue);
  if (!primaries.fullPivLu().isInvertible())
    throw Error("colour space " + space.name + ": its primaries lie on one line, so no RGB spans the white");
  Eigen::Vector3d scale = primaries.partialPivLu().solve(xyToXyz(white));
  space.rgbToXyz = primaries * scale.asDiagonal();
  space.xyzToRgb = space.rgbToXyz.inverse();
  if (!space.rgbToXyz.allFinite() || !space.xyzToRgb.allFinite())
    throw Error("colour space " + space.name + ": its matrices are not finite (a white on a line of two primaries?)");
  return space;
}

Eigen::Vector3d RgbColourSpace::encode(const Eigen::Vector3d& linear) const {
  Eigen::Vector3d out;
  for (int c = 0; c < 3; ++c) {
    auto v = static_cast<float>(linear[c]);
    switch (transfer) {
      case Transfer::Linear: out[c] = linear[c]; break;
      case Transfer::Srgb: out[c] = shared::srgbEncode(v); break;
      case Transfer::Bt2020: out[c] = shared::bt2020Encode(v); break;
    }
  }
  return out;
}

Eigen::Vector3d RgbColourSpace::decode(const Eigen::Vector3d& encoded) const {
  Eigen::Vector3d out;
  for (int c = 0; c < 3; ++c) {
    auto v = static_cast<float>(encoded[c]);
    switch (transfer) {
      case Transfer::Linear: out[c] = encoded[c]; break;
      case Transfer::Srgb: out[c] = shared::srgbDecode(v); break;
      case Transfer::Bt2020: out[c] = shared::bt2020Decode(v); break;
    }
  }
  return out;
}

const RgbColourSpace& colourSpace(std::string_view name) {
  if (name == "p3") name = "display-p3";
  for (const RgbColourSpace& s : spaces())
    if (s.name == name) return s;
  throw Error("unknown colour space '" + std::string(name) +
              "' (known: srgb, display-p3 or p3, rec2020, acescg, aces2065-1)");
}

std::vector<std::string> listColourSpaces() {
  std::vector<std::string> names;
  for (const RgbColourSpace& s : spaces()) names.push_back(s.name);
  return names;
}

Adaptation adaptationFromName(std::string_view name) {
  if (name == "bradford") return Adaptation::Bradford;
  if (name == "cat02") return Adaptation::Cat02;
  if (name == "von-kries") return Adaptation::VonKries;
  throw Error("unknown chromatic adaptation '" + std::string(name) +
              "' (known: bradford, cat02, von-kries)");
}

std::string_view adaptationName(Adaptation adaptation) {
  switch (adaptation) {
    case Adaptation::Bradford: return "bradford";
    case Adaptation::Cat02: return "cat02";
    case Adaptation::VonKries: return "von-kries";
  }
  return "?";
}

Eigen::Matrix3d chromaticAdaptation(Adaptation method, const Eigen::Vector3d& sourceWhiteXyz,
                                    const Eigen::Vector3d& targetWhiteXyz) {
  Eigen::Matrix3d cone = coneMatrix(method);
  Eigen::Vector3d gain = (cone * targetWhiteXyz).cwiseQuotient(cone * sourceWhiteXyz);
  return cone.inverse() * gain.asDiagonal() * cone;
}

Eigen::Matrix3d rgbToRgb(const RgbColourSpace& from, const RgbColourSpace& to, Adaptation method) {
  Eigen::Matrix3d adapt = Eigen::Matrix3d::Identity();
  if (from.white.x != to.white.x || from.white.y != to.white.y)
    adapt = chromaticAdaptation(method, from.whiteXyz(), to.whiteXyz());
  return to.xyzToRgb * adapt * from.rgbToXyz;
}

}  // namespace prism
