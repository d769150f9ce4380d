// The viewer script's `set sky.*` keys (viewer/technique_settings.h).
#include "techniques/atmosphere/viewer/sky_viewer.h"

#include <string_view>

#include <fmt/format.h>

#include "core/error.h"
#include "render/setting_keys.h"
#include "scene/scene_loader.h"
#include "techniques/atmosphere/atmosphere_section.h"

namespace prism::viewer {

bool setSkyKey(Scene& scene, const std::string& key, const std::string& value) {
  if (key.rfind("sky.", 0) != 0) return false;
  auto* sky = scene.techniques.find<atmosphere::AtmosphereSection>();
  if (!sky) throw Error("the scene has no atmosphere");
  atmosphere::AtmosphereSection& a = *sky;
  atmosphere::AtmosphereParameters p = a.parameters;
  std::string_view k = std::string_view(key).substr(4);
  // The scene file's ranges, never clamped (a script says what it means).
  const float elevationLimit = a.kSunElevationLimitDeg, azimuthLimit = a.kSunAzimuthLimitDeg;
  if (k == "elevation") a.sunElevationDeg = render::parseFloatWithin(key, value, -elevationLimit, elevationLimit);
  else if (k == "azimuth") a.sunAzimuthDeg = render::parseFloatWithin(key, value, -azimuthLimit, azimuthLimit);
  else if (k == "turbidity") p.mieAngstromBeta = render::parseFloat(key, value);
  else if (k == "ozone") p.ozoneColumnDu = render::parseFloat(key, value);
  else if (k == "aerosols" || k == "multiple-scattering") {
    if (value != "on" && value != "off") throw Error(fmt::format("{}: expected on or off, got \"{}\"", excerpt(key), excerpt(value)));
    (k == "aerosols" ? p.aerosols : p.multipleScattering) = value == "on";
  }
  else throw Error(fmt::format("unknown setting \"{}\" (sky.elevation, azimuth, turbidity, ozone, aerosols, "
                               "multiple-scattering)", excerpt(key)));
  try {  // nothing changes on an error, which names the key ("Ångström beta" is the turbidity)
    atmosphere::validate(p);
  } catch (const Error& e) {
    throw Error(fmt::format("{}: {}", excerpt(key), e.what()));
  }
  a.parameters = p;
  applyTechniqueLights(scene);
  return true;
}

}  // namespace prism::viewer
