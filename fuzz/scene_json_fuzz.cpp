// Scene files: JSON parsing, the schema's checks and everything the loader builds from them
// (lights' spectra, materials, procedural meshes, glTF references, the techniques' sections).
// The example scenes' models are copied beside the input once, so that seeds reach into glTF.
#include <cstddef>
#include <cstdint>
#include <filesystem>

#include "fuzz/fuzz_input.h"
#include "scene/scene_loader.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static const bool modelsCopied = [] {
    std::filesystem::copy(PRISM_FUZZ_SCENES_DIR "/models", prism::fuzz::scratchFolder() / "models",
                          std::filesystem::copy_options::recursive | std::filesystem::copy_options::skip_existing);
    return true;
  }();
  (void)modelsCopied;
  std::filesystem::path file = prism::fuzz::inputFile({data, size}, "scene.json");
  prism::fuzz::expectOnlyInputErrors([&] { (void)prism::loadScene(file); });
  return 0;
}
