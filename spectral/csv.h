// Reading the CSV files Prism is handed: its own data/ tables and users' spectra.
//
// Every failure is a prism::Error whose message starts with "FILE:LINE:" (LINE:COLUMN for a bad
// field), so a user can go straight to the place. Tokenising (RFC 4180 quoting) is libcsv's;
// the checks are ours: same field count on every row, every number finite, wavelengths
// strictly increasing, the expected columns present.
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

struct CsvRow {
  int line = 0;  // 1-based line in the file
  std::vector<std::string> fields;
};

class CsvTable {
 public:
  static CsvTable read(const std::filesystem::path& path);

  const std::string& path() const { return mPath; }
  const std::vector<std::string>& header() const { return mHeader; }
  const std::vector<CsvRow>& rows() const { return mRows; }
  // Index of a header column; Error naming the file and the column when absent.
  int column(std::string_view name) const;
  // A finite number from a field; Error "FILE:LINE:COLUMN: ..." otherwise.
  double number(const CsvRow& row, int column) const;

 private:
  std::string mPath;
  std::vector<std::string> mHeader;
  std::vector<CsvRow> mRows;
};

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

// Error "PATH:LINE: ..." at the first wavelength that does not increase strictly; `lines` holds
// the source line of each wavelength.
void checkIncreasingWavelengths(const std::string& path, std::span<const double> lambdasNm,
                                std::span<const int> lines);

// A user spectrum file (header + wavelength_nm,value). A value outside [minValue, maxValue] is
// an Error at its place: "PATH:LINE:2: value V is outside [0, 1]" (or "is negative" for a
// bound of 0 below and none above).
TabulatedSpectrum readSpectrumCsv(const std::filesystem::path& path, Extrapolation extrapolation,
                                  double minValue = -std::numeric_limits<double>::infinity(),
                                  double maxValue = std::numeric_limits<double>::infinity());

}  // namespace prism
