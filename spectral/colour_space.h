// RGB colour spaces built from their primaries and white point, and chromatic adaptation.
//
// The RGB→XYZ matrix is derived, never typed: its columns are the primaries' XYZ (Y = 1) scaled
// so that RGB (1, 1, 1) maps to the white's XYZ (SMPTE RP 177-1993 §3.3). Spaces:
//   srgb         IEC 61966-2-1 (BT.709 primaries, D65), sRGB transfer
//   display-p3   DCI-P3 primaries, D65, sRGB transfer (Apple Display P3)
//   rec2020      ITU-R BT.2020, D65, BT.2020 transfer
//   acescg       ACES AP1, ACES white (≈ D60), linear (SMPTE S-2065-1 / Academy S-2014-004)
//   aces2065-1   ACES AP0, ACES white, linear
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include <Eigen/Core>

namespace prism {

struct Chromaticity {
  double x = 0.0;
  double y = 0.0;
};

// XYZ of a chromaticity at luminance Y.
Eigen::Vector3d xyToXyz(Chromaticity xy, double luminanceY = 1.0);
Chromaticity xyzToXy(const Eigen::Vector3d& xyz);

enum class Transfer { Linear, Srgb, Bt2020 };

struct RgbColourSpace {
  std::string name;
  Chromaticity red, green, blue, white;
  Transfer transfer = Transfer::Linear;
  Eigen::Matrix3d rgbToXyz;  // linear RGB → XYZ with white Y = 1
  Eigen::Matrix3d xyzToRgb;

  static RgbColourSpace fromPrimaries(std::string name, Chromaticity red, Chromaticity green,
                                      Chromaticity blue, Chromaticity white, Transfer transfer);
  Eigen::Vector3d whiteXyz() const { return xyToXyz(white); }
  Eigen::Vector3d encode(const Eigen::Vector3d& linear) const;
  Eigen::Vector3d decode(const Eigen::Vector3d& encoded) const;
};

// Error naming the space when unknown; "p3" is accepted for "display-p3".
const RgbColourSpace& colourSpace(std::string_view name);
std::vector<std::string> listColourSpaces();

// Linear chromatic adaptation transforms: XYZ → cone-like space, scale by the ratio of the
// whites there, back to XYZ (von Kries 1902 in the form of CIE 160:2004 §2).
enum class Adaptation { Bradford, Cat02, VonKries };
Adaptation adaptationFromName(std::string_view name);  // "bradford" | "cat02" | "von-kries"
std::string_view adaptationName(Adaptation adaptation);
Eigen::Matrix3d chromaticAdaptation(Adaptation method, const Eigen::Vector3d& sourceWhiteXyz,
                                    const Eigen::Vector3d& targetWhiteXyz);

// Linear RGB in `from` → linear RGB in `to`, adapting between their whites when they differ.
Eigen::Matrix3d rgbToRgb(const RgbColourSpace& from, const RgbColourSpace& to,
                         Adaptation method = Adaptation::Bradford);

}  // namespace prism
