#include "scene/conductors.h"

#include <algorithm>
#include <array>

#include "core/csv.h"
#include "spectral/spectrum_csv.h"
#include "core/data_files.h"
#include "core/error.h"

namespace prism {

namespace {

constexpr std::array<std::string_view, 4> kMetals = {"Ag", "Al", "Au", "Cu"};
constexpr std::array<std::string_view, 3> kExtra = {"CuZn", "MgO", "TiO2"};

// metals_ior.csv: wavelength_nm, then <X>_n, <X>_k for each metal (one shared grid).
ConductorIor fromMetalsTable(std::string_view name) {
  SpectraTable table = SpectraTable::read(dataFile("metals_ior.csv"));
  std::string base(name);
  return {base, table.spectrum(base + "_n", Extrapolation::Clamp).toDense(),
          table.spectrum(base + "_k", Extrapolation::Clamp).toDense()};
}

// conductors_extra_ior.csv, long format: wavelength_nm, material, n, k.
ConductorIor fromExtraTable(std::string_view name) {
  CsvTable csv = CsvTable::read(dataFile("conductors_extra_ior.csv"));
  int lambdaColumn = csv.column("wavelength_nm"), materialColumn = csv.column("material");
  int nColumn = csv.column("n"), kColumn = csv.column("k");
  std::vector<double> lambdas, n, k;
  std::vector<int> lines;
  for (const CsvRow& row : csv.rows()) {
    if (row.fields[static_cast<std::size_t>(materialColumn)] != name) continue;
    lambdas.push_back(csv.number(row, lambdaColumn));
    n.push_back(csv.number(row, nColumn));
    k.push_back(csv.number(row, kColumn));
    lines.push_back(row.line);
  }
  checkIncreasingWavelengths(csv.path(), lambdas, lines);
  std::vector<double> lambdasCopy = lambdas;
  return {std::string(name),
          TabulatedSpectrum(std::move(lambdas), std::move(n), Extrapolation::Clamp).toDense(),
          TabulatedSpectrum(std::move(lambdasCopy), std::move(k), Extrapolation::Clamp).toDense()};
}

}  // namespace

std::vector<std::string> listConductors() {
  std::vector<std::string> names(kMetals.begin(), kMetals.end());
  names.insert(names.end(), kExtra.begin(), kExtra.end());
  return names;
}

ConductorIor conductorIor(std::string_view name) {
  if (std::find(kMetals.begin(), kMetals.end(), name) != kMetals.end()) return fromMetalsTable(name);
  if (std::find(kExtra.begin(), kExtra.end(), name) != kExtra.end()) return fromExtraTable(name);
  std::string known;
  for (const std::string& n : listConductors()) known += (known.empty() ? "" : ", ") + n;
  throw Error("unknown conductor '" + std::string(name) + "' (known: " + known + ")");
}

}  // namespace prism
