// The water in the viewer (registered by techniques/underwater/CMakeLists.txt): its panel and
// its script keys.
#pragma once

#include <memory>
#include <string>

#include "viewer/panel.h"
#include "viewer/technique_settings.h"

namespace prism::viewer {

// The water type and its data set, the camera's depth, the coefficients' multipliers.
std::unique_ptr<Panel> makeWaterPanel();
// water.type T, water.depth M (a TechniqueSetKey).
bool setWaterKey(Scene& scene, const std::string& key, const std::string& value);

}  // namespace prism::viewer
