// Spectra read from CSV files (core/csv.h does the reading and its checks): data/ tables of
// several spectra sharing a wavelength column, and users' spectra.
//
// A user spectrum is a header line and two columns, wavelength in nm and value; the same format
// wherever Prism takes a spectrum from a user.
#pragma once

#include <filesystem>
#include <limits>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "spectral/spectrum.h"

namespace prism {

// Spectra sharing one wavelength column (the first, strictly increasing).
class SpectraTable {
 public:
  // expectedColumns: names that must be present (besides the wavelength column).
  static SpectraTable read(const std::filesystem::path& path,
                           std::span<const std::string_view> expectedColumns = {});

  const std::vector<std::string>& names() const { return mNames; }
  bool contains(std::string_view name) const;
  TabulatedSpectrum spectrum(std::string_view name, Extrapolation extrapolation) const;

 private:
  std::string mPath;
  std::vector<std::string> mNames;
  std::vector<double> mLambdasNm;
  std::vector<std::vector<double>> mColumns;
};

// A user spectrum file (header + wavelength_nm,value). A value outside [minValue, maxValue] is
// an Error at its place: "PATH:LINE:2: value V is outside [0, 1]" (or "is negative" for a
// bound of 0 below and none above).
TabulatedSpectrum readSpectrumCsv(const std::filesystem::path& path, Extrapolation extrapolation,
                                  double minValue = -std::numeric_limits<double>::infinity(),
                                  double maxValue = std::numeric_limits<double>::infinity());

// A lamp's spectrum file, as scenes, the viewer and the colour commands read one: no negative
// value, zero outside its rows; Error "PATH: the lamp has no luminous power …" when ∫ S ȳ dλ = 0
// (its colour would be 0/0).
Spectrum readLampCsv(const std::filesystem::path& path);

}  // namespace prism
