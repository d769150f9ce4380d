// OpenEXR files for linear images: renders, references and ΔE maps. Each file records what its
// channels mean in the string attribute "prism:colour" (float_image.h), and also in the standard
// "chromaticities" attribute where that can say it (linear sRGB; XYZ as OpenEXR's convention of
// primaries (1,0), (0,1), (0,0) and white (1/3, 1/3)), so other tools read the colours right.
#pragma once

#include <filesystem>
#include <optional>
#include <string>

#include <Eigen/Core>

#include "imaging/float_image.h"

namespace prism::imaging {

enum class ExrPrecision {
  Float,  // 32-bit: exact, any range
  Half,   // 16-bit: relative precision 2⁻¹¹, |values| ≤ 65504 (larger is an Error, not an ∞)
};

// "prism:displayWhite" (float): the luminance, in the image's units (cd/m² for Prism's renders),
// that the exposure maps to display white. Comparisons read it as the white of CIELAB.
inline constexpr const char* kDisplayWhiteAttribute = "prism:displayWhite";
// "prism:part" (string): what a part of a split render says it is (batch/reference_part.h).
inline constexpr const char* kPartAttribute = "prism:part";
// "prism:camera" (string) and "prism:cameraToXyz" (m33d, row-major): a camera's raw RGB says which
// camera it is and the matrix its frame is shown through (the camera's ColorChecker fit under the
// scene's light), which makes it colorimetric: compare takes a camera's frame into CIE 1931 XYZ by it.
inline constexpr const char* kCameraAttribute = "prism:camera";
inline constexpr const char* kCameraToXyzAttribute = "prism:cameraToXyz";

struct ExrCamera {
  std::string name;       // as `prism colour list cameras` names it
  Eigen::Matrix3d toXyz;  // camera RGB → CIE 1931 XYZ, on the image's scale
};

struct ExrWriteOptions {
  ColourMeaning colour = ColourMeaning::LinearSrgb;
  ExrPrecision precision = ExrPrecision::Float;
  std::optional<double> displayWhite = std::nullopt;  // written as kDisplayWhiteAttribute when set
  std::optional<ExrCamera> camera = std::nullopt;     // with ColourMeaning::CameraRgb only
};

// Channels R, G, B (+ A) whatever they hold, CIE XYZ in them with OpenEXR's XYZ chromaticities
// (its convention for XYZ files), "Y" for one channel. ZIP-compressed scan lines, written to
// memory and then to `path` atomically: a reader never sees half a file, and a failure leaves
// nothing behind (core/atomic_file.h). Creates missing folders. Error naming the path when it
// fails.
void writeExr(const std::filesystem::path& path, const FloatImage& image,
              const ExrWriteOptions& options = {});

// How a render's tristimulus under `observer` is written: its meaning (tristimulusMeaning), float,
// the display white, and for a camera its name and `cameraToXyz`, the matrix its frame is shown
// through (render::DisplayInputs::tristimulusToXyz; ignored for the CIE observers).
ExrWriteOptions tristimulusExr(const Observer& observer, double displayWhite, const Eigen::Matrix3d& cameraToXyz);

struct ExrImage {
  FloatImage image;
  ColourMeaning colour = ColourMeaning::LinearSrgb;
  std::optional<double> displayWhite;  // kDisplayWhiteAttribute, when the file has it
  std::optional<ExrCamera> camera;     // kCameraAttribute and kCameraToXyzAttribute, when it has them
                                       // (a part's are its own header's: batch/reference_part.h)
  // Its data window (what `image` holds) is its display window; false for a crop, an overscan, or a
  // band of a split render (a reference part's rows).
  bool wholeImage = true;
  // kPartAttribute, when the file has it: a part of a split render (batch/reference_part.h).
  std::optional<std::string> part;
};

// The largest side readExr takes (what `prism render` can write: its --width/--height limit).
inline constexpr int kMaxExrSide = 16384;

// Reads R, G, B (+ A), else X, Y, Z (+ A), else Y alone as one channel, in any pixel type, as
// float. The meaning is "prism:colour" when present, else told by the chromaticities (Rec. 709
// with D65 → linear-srgb; the XYZ convention → xyz; anything else → other-rgb), else xyz for X,
// Y, Z channels, else linear-srgb (OpenEXR's default for files without chromaticities).
// Error naming the file, on one line, when it cannot: also for a header attribute larger than the
// file, for an image wider or higher than kMaxExrSide, and for multi-part and deep files.
ExrImage readExr(const std::filesystem::path& path);

// OpenEXR trusts an attribute's stated size (a 793-byte file claiming a 1.6 GB attribute kept it
// busy for seconds; found by fuzzing) and allocates by the data window and tile size as it opens
// a file: Error naming the file and the attribute unless every attribute of the header fits in
// what is left of the file and holds what its size says, and the data window and tiles are 1 to
// kMaxExrSide a side; multi-part and deep files are refused. readExr and readExrBand call it.
void checkExrHeaderSizes(const std::filesystem::path& path);

}  // namespace prism::imaging
