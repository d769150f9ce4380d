#include "spectral/colour_checker.h"

#include <cmath>

#include "core/csv.h"
#include "spectral/spectrum_csv.h"
#include "core/data_files.h"
#include "core/error.h"

namespace prism {
namespace {

std::vector<ColourCheckerPatch> load() {
  SpectraTable spectra = SpectraTable::read(dataFile("colorchecker24.csv"));
  CsvTable layout = CsvTable::read(dataFile("colorchecker24_patches.csv"));
  int nameCol = layout.column("name");
  int rowCol = layout.column("row");
  int columnCol = layout.column("column");
  std::vector<ColourCheckerPatch> patches;
  for (const CsvRow& row : layout.rows()) {
    const std::string& name = row.fields[static_cast<std::size_t>(nameCol)];
    if (!spectra.contains(name))
      throw Error(layout.path() + ":" + std::to_string(row.line) + ": patch '" + name +
                  "' has no column in colorchecker24.csv");
    patches.push_back({name, static_cast<int>(std::lround(layout.number(row, rowCol))),
                       static_cast<int>(std::lround(layout.number(row, columnCol))),
                       spectra.spectrum(name, Extrapolation::Clamp).toDense()});
  }
  if (patches.size() != 24) throw Error(layout.path() + ": expected 24 patches, found " +
                                        std::to_string(patches.size()));
  return patches;
}

}  // namespace

const std::vector<ColourCheckerPatch>& colourChecker() {
  static const std::vector<ColourCheckerPatch> patches = load();
  return patches;
}

std::vector<Spectrum> colourCheckerReflectances() {
  std::vector<Spectrum> out;
  for (const ColourCheckerPatch& patch : colourChecker()) out.push_back(patch.reflectance);
  return out;
}

}  // namespace prism
