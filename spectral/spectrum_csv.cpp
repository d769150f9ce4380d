#include "spectral/spectrum_csv.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <sstream>

#include "core/csv.h"
#include "core/error.h"
#include "spectral/observer.h"

namespace prism {

SpectraTable SpectraTable::read(const std::filesystem::path& path,
                                std::span<const std::string_view> expectedColumns) {
  CsvTable csv = CsvTable::read(path);
  SpectraTable table;
  table.mPath = csv.path();
  if (csv.header().front() != "wavelength_nm")
    throw Error(table.mPath + ":" + std::to_string(csv.headerLine()) + ": first column must be 'wavelength_nm', found '" +
                csv.header().front() + "'");
  for (std::string_view name : expectedColumns) csv.column(name);
  table.mNames.assign(csv.header().begin() + 1, csv.header().end());
  table.mColumns.resize(table.mNames.size());
  std::vector<int> lines;
  for (const CsvRow& row : csv.rows()) {
    table.mLambdasNm.push_back(csv.number(row, 0));
    lines.push_back(row.line);
    for (std::size_t c = 0; c < table.mNames.size(); ++c)
      table.mColumns[c].push_back(csv.number(row, static_cast<int>(c + 1)));
  }
  checkIncreasingWavelengths(table.mPath, table.mLambdasNm, lines);
  return table;
}

bool SpectraTable::contains(std::string_view name) const {
  return std::find(mNames.begin(), mNames.end(), name) != mNames.end();
}

TabulatedSpectrum SpectraTable::spectrum(std::string_view name, Extrapolation extrapolation) const {
  auto it = std::find(mNames.begin(), mNames.end(), name);
  if (it == mNames.end()) throw Error(mPath + ": no spectrum named '" + std::string(name) + "'");
  return TabulatedSpectrum(mLambdasNm, mColumns[static_cast<std::size_t>(it - mNames.begin())],
                           extrapolation);
}

TabulatedSpectrum readSpectrumCsv(const std::filesystem::path& path, Extrapolation extrapolation,
                                  double minValue, double maxValue) {
  CsvTable csv = CsvTable::read(path);
  if (csv.header().size() != 2)
    throw Error(csv.path() + ":" + std::to_string(csv.headerLine()) + ": a spectrum file has two columns (wavelength in nm, value), found " +
                std::to_string(csv.header().size()));
  double number = 0.0;
  const std::string& first = csv.header().front();
  const auto parsed = std::from_chars(first.data(), first.data() + first.size(), number);
  if (!first.empty() && parsed.ec == std::errc() && parsed.ptr == first.data() + first.size())
    throw Error(csv.path() + ":" + std::to_string(csv.headerLine()) +
                ": expected a header line (e.g. wavelength_nm,value) before the numbers, got " + first);
  std::vector<double> lambdas, values;
  std::vector<int> lines;
  for (const CsvRow& row : csv.rows()) {
    lambdas.push_back(csv.number(row, 0));
    double v = csv.number(row, 1);
    if (v < minValue || v > maxValue) {
      std::ostringstream bounds;
      bounds << "[" << minValue << ", " << maxValue << "]";
      throw Error(csv.path() + ":" + std::to_string(row.line) + ":2: value " + row.fields[1] +
                  (minValue == 0.0 && std::isinf(maxValue) ? " is negative"
                                                           : " is outside " + bounds.str()));
    }
    values.push_back(v);
    lines.push_back(row.line);
  }
  checkIncreasingWavelengths(csv.path(), lambdas, lines);
  // Wholly outside what Prism renders, the spectrum would be its end values extrapolated: a
  // reflectance at 100 and 200 nm read as a flat grey.
  if (lambdas.back() < kLambdaMinNm || lambdas.front() > kLambdaMaxNm) {
    std::ostringstream message;
    message << csv.path() << ": its wavelengths (" << lambdas.front() << "–" << lambdas.back() << " nm) lie outside "
            << kLambdaMinNm << "–" << kLambdaMaxNm << " nm, the range Prism renders";
    throw Error(message.str());
  }
  return TabulatedSpectrum(std::move(lambdas), std::move(values), extrapolation);
}

Spectrum readLampCsv(const std::filesystem::path& path) {
  Spectrum lamp = readSpectrumCsv(path, Extrapolation::Zero, 0.0).toDense();
  if (!(luminousIntegral(lamp) > 0.0))
    throw Error(path.string() + ": the lamp has no luminous power (683 lm/W · ∫ S ȳ dλ = 0 over 360–830 nm)");
  return lamp;
}

}  // namespace prism
