// `prism view SCENE.json`: the interactive viewer (viewer/viewer.h) on a scene, with the same
// starting settings as `prism render`.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "app/render_commands.h"

namespace prism::app {

struct ViewOptions {
  std::filesystem::path scene;
  std::filesystem::path script;
  std::vector<std::string> sets;
  SettingsOptions settings;
};
int runView(const ViewOptions& options);

}  // namespace prism::app
