// 8-bit images: the glTF textures' PNG/JPEG decoder (stb, behind Prism's size checks) and the PNG
// reader of `prism compare`.
#include <cstddef>
#include <cstdint>
#include <filesystem>

#include "fuzz/fuzz_input.h"
#include "imaging/png_file.h"
#include "scene/gltf_loader.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  prism::fuzz::expectOnlyInputErrors([&] { (void)prism::decodeImage({data, size}, true, "fuzz input"); });
  std::filesystem::path file = prism::fuzz::inputFile({data, size}, "image.png");
  prism::fuzz::expectOnlyInputErrors([&] { (void)prism::imaging::readPng8(file); });
  return 0;
}
