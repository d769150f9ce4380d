// The 24-patch ColorChecker Classic (BabelColor average of 30 charts, 380–730 nm at 10 nm),
// in chart order: row-major, dark skin at the top left. Reflectances are extended beyond the
// measured band with their end values (Extrapolation::Clamp).
#pragma once

#include <string>
#include <vector>

#include "spectral/spectrum.h"

namespace prism {

struct ColourCheckerPatch {
  std::string name;
  int row = 0;     // 1–4
  int column = 0;  // 1–6
  Spectrum reflectance;
};

const std::vector<ColourCheckerPatch>& colourChecker();
// The 24 reflectances alone, in chart order (a wavelength fit's training or test set).
std::vector<Spectrum> colourCheckerReflectances();

}  // namespace prism
