// Users' spectrum files (header + wavelength_nm,value), as lights' and materials' "csv:" spectra,
// read with both extrapolations and a reflectance's [0, 1] bounds.
#include <cstddef>
#include <cstdint>
#include <filesystem>

#include "fuzz/fuzz_input.h"
#include "spectral/spectrum_csv.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  std::filesystem::path file = prism::fuzz::inputFile({data, size}, "spectrum.csv");
  prism::fuzz::expectOnlyInputErrors(
      [&] { (void)prism::readSpectrumCsv(file, prism::Extrapolation::Zero); });
  prism::fuzz::expectOnlyInputErrors(
      [&] { (void)prism::readSpectrumCsv(file, prism::Extrapolation::Clamp, 0.0, 1.0); });
  return 0;
}
