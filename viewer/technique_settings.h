// The script's `set` keys of the techniques, one function per technique, each the only place in
// the script that knows its technique's part of the Scene, and each defined in its technique's
// folder (techniques/<name>/viewer/) and registered by its prism_technique() call. Each returns
// false when the key is not its technique's, and throws Error (the scene unchanged) when the
// value is bad or the scene lacks the technique; on success the scene's derived data is up to
// date and the renderers must be told (Changes::scene).
#pragma once

#include <span>
#include <string>

#include "scene/scene.h"

namespace prism::viewer {

using TechniqueSetKey = bool (*)(Scene& scene, const std::string& key, const std::string& value);

// Every technique's, in registration order.
std::span<const TechniqueSetKey> techniqueSetKeys();

}  // namespace prism::viewer
