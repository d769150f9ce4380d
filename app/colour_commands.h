// `prism colour …`: colorimetry for people (text) and scripts (--json). Each command writes its
// result to stdout and throws prism::Error on bad input.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "spectral/spectrum.h"

namespace prism::app {

struct XyzOptions {
  std::string illuminant = "D65";
  std::string observer = "cie1931";
  std::string reflectanceFile;        // a spectral CSV, or
  std::vector<double> rgb;            // an RGB albedo in `gamut` (linear unless `encoded`)
  std::string gamut = "srgb";
  bool encoded = false;
  // When `sample` is set, also estimate the value from sampled wavelengths (as a renderer would)
  // and report its CIEDE2000 distance to the 1 nm integral.
  bool sample = false;
  int wavelengthCount = 16;
  std::vector<double> rangeNm{360.0, 830.0};
  std::string strategy = "uniform";
  unsigned seed = 0;
  bool json = false;
};
void colourXyz(const XyzOptions& options);

struct DeltaEOptions {
  std::vector<std::vector<double>> labs;  // exactly two
  std::string formula = "2000";
  bool json = false;
};
void colourDeltaE(const DeltaEOptions& options);

struct CctOptions {
  double cctK = 6504.0;
  int stepNm = 1;
  std::string output;  // file, or stdout when empty
};
void colourCct(const CctOptions& options);

struct ConvertOptions {
  std::string from = "srgb";
  std::string to = "srgb";
  std::vector<double> values;
  std::optional<std::string> adaptation;  // unset: bradford between two RGB spaces; given with xyz, refused
  bool linear = false;
  bool json = false;
};
void colourConvert(const ConvertOptions& options);

struct CameraMatrixOptions {
  std::string camera;
  std::string illuminant = "D65";
  bool json = false;
};
void colourCameraMatrix(const CameraMatrixOptions& options);

// A metamer of a reflectance (a ColorChecker patch by name, or a spectral CSV): the same colour
// under `match`, as different as possible under `target` (techniques/prt/metamer.h); prints its
// CIEDE2000 from the original under each illuminant of `under`, and writes it as CSV when asked.
struct MetamerOptions {
  std::string reflectance;
  std::string match = "D65";
  std::string target = "A";
  std::vector<std::string> under{"D65", "A", "F2"};
  std::string observer = "cie1931";
  std::string output;  // CSV wavelength_nm,reflectance at 1 nm (360–830)
  bool json = false;
};
void colourMetamer(const MetamerOptions& options);
// A ColorChecker patch by name, else a spectral CSV, else a patch by its name as a user types it
// (any case, '_' or '-' for spaces, a grey's density left out: Dark_Skin, white_9.5); Error naming
// `option` and listing the patches when none.
Spectrum patchOrFileReflectance(const std::string& text, const std::string& option);

// The ColorChecker's 24 patches as a spectral texture (docs/spectral-texture.md): 6 × 4 cells of
// `cell` × `cell` texels in chart order, row 1 at the top; the samples form at 5 nm over 380–780 nm,
// or with `basis` k > 0 the coefficients form over the k leading singular vectors of the 24
// spectra (Error when k is too few to keep every reflectance within the reader's [0, 1] ± 0.01).
struct SpectralTextureOptions {
  std::string output;  // .exr
  int cell = 4;
  int basis = 0;
};
void colourSpectralTexture(const SpectralTextureOptions& options);

// what: illuminants | observers | cameras | spaces
void colourList(const std::string& what, bool json);

}  // namespace prism::app
