// Reading the CSV files Prism is handed: its own data/ tables and users' files. Blank lines and
// lines whose first non-blank character is '#' (comments, as spectral data files often start) are
// skipped; the first other line is the header.
//
// Every failure is a prism::Error whose message starts with "FILE:LINE:" (LINE:COLUMN for a bad
// field), so a user can go straight to the place. Tokenising (RFC 4180 quoting) is libcsv's;
// the checks are ours: same field count on every row, every number finite, wavelengths
// strictly increasing, the expected columns present.
#pragma once

#include <filesystem>
#include <span>
#include <string>
#include <string_view>
#include <vector>

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
  int headerLine() const { return mHeaderLine; }  // 1-based, after any comments
  const std::vector<CsvRow>& rows() const { return mRows; }
  // Index of a header column; Error naming the file and the column when absent.
  int column(std::string_view name) const;
  // A finite number from a field; Error "FILE:LINE:COLUMN: ..." otherwise.
  double number(const CsvRow& row, int column) const;

 private:
  std::string mPath;
  std::vector<std::string> mHeader;
  int mHeaderLine = 0;
  std::vector<CsvRow> mRows;
};

// Error "PATH:LINE: ..." at the first wavelength that is not positive or does not increase
// strictly; `lines` holds the source line of each wavelength.
void checkIncreasingWavelengths(const std::string& path, std::span<const double> lambdasNm,
                                std::span<const int> lines);

}  // namespace prism
