// The frame keys of render/setting_keys.h as options of a CLI11 command (prism's main.cpp).
#pragma once

#include <CLI/CLI.hpp>

#include <algorithm>
#include <functional>
#include <map>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "app/camera_option.h"
#include "app/parse_error_hint.h"
#include "app/settings_command.h"
#include "render/setting_keys.h"

namespace prism::app {

inline const char* settingTypeName(render::SettingType type) {
  using render::SettingType;
  return type == SettingType::Integer ? "INT" : type == SettingType::Number ? "NUMBER" : type == SettingType::Range ? "MIN,MAX" : "NAME";
}

// The frame keys of render/setting_keys.h as options of a command: names, help and defaults come
// from the table; what was given is handed on as text, parsed by the table (frameSettings).
// CLI11's check of a --camera value, as it is parsed: not empty (given empty, it was taken for no
// camera, and a script's unset variable rendered CIE 1931 XYZ without a word). A malformed command
// line, exit 2; a name that is no camera's is bad input, cameraOption's, exit 1. (Here, not in
// camera_option.h, which files without CLI11 include: its headers cost ~15 s a unit.)
inline CLI::Validator cameraName() {
  return CLI::Validator(
      [](std::string& name) {
        return name.empty() ? std::string("\"\" is not a camera (see `prism colour list cameras`)") : std::string();
      },
      "");
}

class CliSettings {
 public:
  // The keys `takes` accepts (default: every one; a command leaves out those it gives another
  // meaning or has no use for, rather than take them and do nothing), and --camera where it takes
  // the observer (the camera is one).
  void addTo(CLI::App* command, const std::function<bool(std::string_view key)>& takes = {}) {
    const render::FrameSettings defaults;
    for (const render::SettingKey& key : render::frameSettingKeys()) {
      if (takes && !takes(key.name)) continue;
      std::string& text = mTexts[key.name];  // a map: the references CLI11 keeps stay valid
      std::string help = key.help + ": " + key.expects;
      CLI::Option* option = key.type == render::SettingType::Switch
                                ? command->add_flag("--" + key.name + "{on}", text, help + " (--" + key.name + " is on)")
                                : command->add_option("--" + key.name, text, help)->type_name(settingTypeName(key.type));
      option->default_str(key.print(defaults));
      // A number written otherwise is a malformed command line (exit 2), as for every other
      // number option: "--width 0x40" was bad input, exit 1, where "--frames 0x20" was exit 2.
      if (key.type == render::SettingType::Integer) option->check(decimalWholeNumber());
      if (key.type == render::SettingType::Number) option->check(decimalNumber(true));
      mOptions.emplace_back(key.name, option);
    }
    if (takes && !takes("observer")) return;
    CLI::Option* camera = command->add_option("--camera", mCamera, "a camera as the observer (raw camera RGB, fitted matrix for display)")
                              ->check(cameraName());
    // One observer: given both, the camera used to replace --observer without a word.
    for (const auto& [name, option] : mOptions)
      if (name == "observer") camera->excludes(option);
  }

  // Another help text for one key on this command (the viewer's window takes a narrower range
  // than the key table's).
  void describe(std::string_view key, const std::string& help) {
    for (const auto& [name, option] : mOptions)
      if (name == key) option->description(help);
  }

  // Whether `option` is one of this command's keys (their text is parsed by the key table).
  bool owns(const CLI::Option* option) const {
    return std::any_of(mOptions.begin(), mOptions.end(), [&](const auto& named) { return named.second == option; });
  }

  SettingsOptions given() const {
    SettingsOptions o;
    for (const auto& [name, option] : mOptions) {
      if (option->count() > 0) o.values.emplace_back(name, mTexts.at(name));
    }
    o.camera = mCamera;
    return o;
  }

 private:
  std::map<std::string, std::string> mTexts;
  std::vector<std::pair<std::string, CLI::Option*>> mOptions;
  std::string mCamera;
};

}  // namespace prism::app
