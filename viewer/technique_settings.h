// The script's `set` keys of the techniques, one function per technique, each the only place in
// the script that knows its technique's part of the Scene, and each defined in its technique's
// folder (techniques/<name>/viewer/<name>_settings.cpp); this list is their registration. Each returns false when the key is not
// its technique's, and throws Error (the scene unchanged) when the value is bad or the scene
// lacks the technique; on success the scene's derived data is up to date and the renderers must
// be told (Changes::scene).
#pragma once

#include <string>

#include "scene/scene.h"

namespace prism::viewer {

// water.type T, water.depth M (techniques/underwater).
bool setWaterKey(Scene& scene, const std::string& key, const std::string& value);
// sky.elevation, sky.azimuth (degrees), sky.turbidity, sky.ozone, sky.aerosols on|off,
// sky.multiple-scattering on|off (techniques/atmosphere).
bool setSkyKey(Scene& scene, const std::string& key, const std::string& value);

}  // namespace prism::viewer
