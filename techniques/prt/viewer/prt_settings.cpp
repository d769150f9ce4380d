// The viewer script's `set prt.*` keys (viewer/technique_settings.h).
#include <cmath>

#include "core/error.h"
#include "render/setting_keys.h"
#include "scene/scene_loader.h"
#include "techniques/prt/prt_section.h"
#include "techniques/prt/viewer/prt_viewer.h"

namespace prism::viewer {

bool setPrtKey(Scene& scene, const std::string& key, const std::string& value) {
  if (key != "prt.mode" && key != "prt.basis" && key != "prt.illuminant" && key != "prt.rotation" &&
      key != "prt.sun-elevation" && key != "prt.sun-azimuth")
    return false;
  auto* s = scene.techniques.find<prt::PrtSection>();
  if (!s) throw Error("the scene has no prt section");
  if (key == "prt.sun-elevation" || key == "prt.sun-azimuth") {
    if (!s->sky) throw Error(key + ": the prt environment is not the spectral sky (\"atmosphere\")");
    const bool elevation = key == "prt.sun-elevation";
    float degrees = render::parseFloat(key, value);
    if (!(std::abs(degrees) <= (elevation ? 90.0f : 360.0f)))
      throw Error(key + ": expected degrees in " + (elevation ? "[-90, 90]" : "[-360, 360]") + ", got " + excerpt(value));
    (elevation ? s->sky->atmosphere.sunElevationDeg : s->sky->atmosphere.sunAzimuthDeg) = degrees;
    applyTechniqueLights(scene);  // the sun light follows
    return true;
  }
  if (key == "prt.mode") {
    for (prt::PrtMode m : {prt::PrtMode::Spectral, prt::PrtMode::RgbPrt, prt::PrtMode::Reference5nm}) {
      if (value == prt::prtModeName(m)) {
        s->mode = m;
        return true;
      }
    }
    throw Error("prt.mode: expected spectral, rgb-prt or reference-5nm, got '" + excerpt(value) + "'");
  }
  if (key == "prt.basis") {
    s->basis = static_cast<int>(render::parseInteger(key, value, 1, shared::kPrtMaxBasis));
  } else if (key == "prt.illuminant") {
    if (s->map || s->sky)
      throw Error(std::string("prt.illuminant: the prt environment is ") + (s->map ? "a map" : "the spectral sky (\"atmosphere\")") +
                  ", lit by no illuminant");
    prt::environmentIlluminant(value);  // Error naming it, before anything changes
    s->illuminant = value;
  } else {
    float degrees = render::parseFloat(key, value);
    if (!(std::abs(degrees) <= 360.0f)) throw Error("prt.rotation: expected degrees in [-360, 360], got " + excerpt(value));
    s->rotationDeg = degrees;
    applyTechniqueLights(scene);  // the spectral sky's sun turns with it
  }
  return true;
}

}  // namespace prism::viewer
