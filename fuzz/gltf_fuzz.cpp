// glTF 2.0 files, .gltf (JSON, data: URIs or files beside it) or .glb (by its magic), through
// tinygltf and Prism's own checks, into a scene. The example models are copied beside the input
// once, so that relative buffer and image URIs resolve.
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <filesystem>

#include "fuzz/fuzz_input.h"
#include "scene/gltf_loader.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static const bool modelsCopied = [] {
    std::filesystem::copy(PRISM_FUZZ_SCENES_DIR "/models", prism::fuzz::scratchFolder(),
                          std::filesystem::copy_options::recursive | std::filesystem::copy_options::skip_existing);
    return true;
  }();
  (void)modelsCopied;
  bool binary = size >= 4 && std::memcmp(data, "glTF", 4) == 0;
  std::filesystem::path file = prism::fuzz::inputFile({data, size}, binary ? "input.glb" : "input.gltf");
  prism::fuzz::expectOnlyInputErrors([&] {
    prism::Scene scene;
    prism::GltfPlacement placement;
    placement.emissionLuminance = 100.0f;  // so that an emitting file reaches its emission's reading
    prism::appendGltf(file, prism::fuzz::scratchFolder(), placement, scene);
  });
  return 0;
}
