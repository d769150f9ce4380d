// The viewer script's `set water.*` keys (viewer/technique_settings.h).
#include "techniques/underwater/viewer/water_viewer.h"

#include "core/error.h"
#include "core/json_schema.h"
#include "render/setting_keys.h"
#include "techniques/underwater/water_section.h"

namespace prism::viewer {

bool setWaterKey(Scene& scene, const std::string& key, const std::string& value) {
  if (key != "water.type" && key != "water.depth") return false;
  auto* water = scene.techniques.find<underwater::WaterSection>();
  if (!water) throw Error("the scene has no water");
  if (key == "water.type") water->type = value;
  else  // the scene's own limit, said in the message (it said 3.4e38, then refused 1e30 at ±1e12)
    water->depthM = render::parseFloatWithin(key, value, 0.0f, static_cast<float>(schema::kFloatInputLimit));
  water->resolve();
  return true;
}

}  // namespace prism::viewer
