// Upsampling-table files (the cache's entries and `prism lut -o`): header, sizes, checksum.
#include <cstddef>
#include <cstdint>
#include <filesystem>

#include "fuzz/fuzz_input.h"
#include "spectral/rgb_to_spectrum_table.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  std::filesystem::path file = prism::fuzz::inputFile({data, size}, "table.bin");
  prism::fuzz::expectOnlyInputErrors([&] { (void)prism::RgbToSpectrumTable::load(file); });
  return 0;
}
