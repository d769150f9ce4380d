// OpenEXR images as `prism compare` and the reference's readers take them.
#include <cstddef>
#include <cstdint>
#include <filesystem>

#include "fuzz/fuzz_input.h"
#include "imaging/exr_file.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  std::filesystem::path file = prism::fuzz::inputFile({data, size}, "image.exr");
  prism::fuzz::expectOnlyInputErrors([&] { (void)prism::imaging::readExr(file); });
  return 0;
}
