// The viewer's settings files (load-settings, --settings) and its frame keys: the input is tried
// as a settings file, and as `KEY VALUE` lines through the script's `set` (applyViewSetting: the
// command line's frame keys, right.KEY, split, heat-map).
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>

#include "fuzz/fuzz_input.h"
#include "viewer/viewer_settings.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  std::filesystem::path file = prism::fuzz::inputFile({data, size}, "settings.json");
  prism::fuzz::expectOnlyInputErrors([&] {
    prism::viewer::ViewSettings view;
    prism::Camera camera;
    prism::viewer::loadViewSettings(file, view, camera);
  });
  std::string_view text(reinterpret_cast<const char*>(data), size);
  prism::viewer::ViewSettings view;
  for (std::size_t start = 0; start < text.size();) {
    std::size_t end = text.find('\n', start);
    if (end == std::string_view::npos) end = text.size();
    std::string_view line = text.substr(start, end - start);
    std::size_t space = line.find(' ');
    if (space != std::string_view::npos) {
      prism::fuzz::expectOnlyInputErrors(
          [&] { (void)prism::viewer::applyViewSetting(view, line.substr(0, space), line.substr(space + 1)); });
    }
    start = end + 1;
  }
  return 0;
}
