// The command line's `--set PATH=VALUE` overrides of a scene: each line of the input is one
// override, applied to the example scene with spheres, lights and materials (the viewer's script
// `set` keys of the techniques go through the same loader).
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "fuzz/fuzz_input.h"
#include "scene/scene_loader.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  std::string_view text(reinterpret_cast<const char*>(data), size);
  std::vector<std::string> sets;
  for (std::size_t start = 0; start < text.size();) {
    std::size_t end = text.find('\n', start);
    if (end == std::string_view::npos) end = text.size();
    sets.emplace_back(text.substr(start, end - start));
    start = end + 1;
  }
  prism::fuzz::expectOnlyInputErrors(
      [&] { (void)prism::loadScene(PRISM_FUZZ_SCENES_DIR "/spheres_led.json", sets); });
  return 0;
}
