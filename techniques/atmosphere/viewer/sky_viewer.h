// The sky in the viewer (registered by techniques/atmosphere/CMakeLists.txt): its panel and its
// script keys.
#pragma once

#include <memory>
#include <string>

#include "viewer/panel.h"
#include "viewer/technique_settings.h"

namespace prism::viewer {

// The sun's direction and the atmosphere's parameters.
std::unique_ptr<Panel> makeSkyPanel();
// sky.elevation, sky.azimuth (degrees), sky.turbidity, sky.ozone, sky.aerosols on|off,
// sky.multiple-scattering on|off (a TechniqueSetKey).
bool setSkyKey(Scene& scene, const std::string& key, const std::string& value);

}  // namespace prism::viewer
