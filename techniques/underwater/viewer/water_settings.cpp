// The viewer script's `set water.*` keys (viewer/technique_settings.h).
#include "techniques/underwater/viewer/water_viewer.h"

#include <limits>

#include "core/error.h"
#include "render/setting_keys.h"
#include "techniques/underwater/water_section.h"

namespace prism::viewer {

bool setWaterKey(Scene& scene, const std::string& key, const std::string& value) {
  if (key != "water.type" && key != "water.depth") return false;
  auto* water = scene.techniques.find<underwater::WaterSection>();
  if (!water) throw Error("the scene has no water");
  if (key == "water.type") water->type = value;
  else water->depthM = render::parseFloatWithin(key, value, 0.0f, std::numeric_limits<float>::max());  // never clamped
  water->resolve();
  return true;
}

}  // namespace prism::viewer
