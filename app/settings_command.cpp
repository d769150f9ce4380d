#include "app/settings_command.h"

#include <fmt/format.h>

#include "render/setting_keys.h"

namespace prism::app {

void printSettings(const SettingsOptions& options, bool keys) {
  if (keys) {
    const render::FrameSettings defaults;
    fmt::print("| key | values | default | what |\n|---|---|---|---|\n");
    for (const render::SettingKey& k : render::frameSettingKeys()) {
      fmt::print("| `{}` | {} | `{}` | {} |\n", k.name, k.expects, k.print(defaults), k.help);
    }
    return;
  }
  for (const auto& [key, value] : render::frameSettingValues(frameSettings(options))) fmt::print("{} {}\n", key, value);
}

}  // namespace prism::app
