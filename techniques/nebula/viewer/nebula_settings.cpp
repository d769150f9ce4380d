// The viewer script's `set nebula.*` keys (viewer/technique_settings.h).
#include <cmath>
#include <string_view>

#include <fmt/format.h>

#include "core/error.h"
#include "render/setting_keys.h"
#include "techniques/nebula/nebula_section.h"
#include "techniques/nebula/viewer/nebula_viewer.h"

namespace prism::viewer {
namespace {

float nonNegative(const std::string& key, const std::string& value) {
  float v = render::parseFloat(key, value);
  if (!(v >= 0.0f)) throw Error(key + ": expected a number ≥ 0, got " + excerpt(value));
  return v;
}

constexpr std::string_view kStarPrefix = "nebula.star.";
constexpr std::string_view kPassbandPrefix = "nebula.passband.";

// A nebula.passband.C.shift_nm or .width key (C the channel, 0..2): false for any other key.
bool setPassbandKey(nebula::NebulaSection* s, const std::string& key, const std::string& value) {
  if (key.rfind(kPassbandPrefix, 0) != 0) return false;
  const std::size_t dot = key.find('.', kPassbandPrefix.size());
  const std::string what = dot == std::string::npos ? std::string() : key.substr(dot + 1);
  if (what != "shift_nm" && what != "width") return false;
  if (!s) throw Error("the scene has no nebula section");
  const long channel = render::parseInteger(key, key.substr(kPassbandPrefix.size(), dot - kPassbandPrefix.size()), 0, 2);
  std::array<nebula::PassbandEdit, 3> edits = s->model.passbands;
  nebula::PassbandEdit& e = edits[static_cast<std::size_t>(channel)];
  (what == "shift_nm" ? e.shiftNm : e.widthScale) = render::parseFloat(key, value);
  try {
    nebula::editedFilterSet(nebula::filterSet(s->model.filters), edits);
  } catch (const Error& x) {
    throw Error(key + ": " + x.what());
  }
  s->model.passbands = edits;
  return true;
}

// What a nebula.star.I.<what> key sets ("temperature", "luminosity", "position"); empty for any
// other key.
std::string starKeyWhat(const std::string& key) {
  if (key.rfind(kStarPrefix, 0) != 0) return {};
  const std::size_t dot = key.find('.', kStarPrefix.size());
  if (dot == std::string::npos) return {};
  std::string what = key.substr(dot + 1);
  return what == "temperature" || what == "luminosity" || what == "position" ? what : std::string();
}

// A nebula.star.I.<what> key; throws for a star the section lacks.
bool setStarKey(nebula::NebulaSection& s, const std::string& key, const std::string& value) {
  const std::string what = starKeyWhat(key);
  if (what.empty()) return false;
  const std::size_t dot = key.find('.', kStarPrefix.size());
  const long index = render::parseInteger(key, key.substr(kStarPrefix.size(), dot - kStarPrefix.size()), 0, 1 << 20);
  if (static_cast<std::size_t>(index) >= s.model.stars.size())
    throw Error(fmt::format("{}: the nebula has {} star(s)", key, s.model.stars.size()));
  nebula::NebulaStar& star = s.model.stars[static_cast<std::size_t>(index)];
  if (what == "temperature") {
    float k = render::parseFloat(key, value);
    if (!(k >= nebula::kMinStarTemperatureK && k <= nebula::kMaxStarTemperatureK))
      throw Error(key + ": expected kelvins in [1000, 100000], got " + excerpt(value));
    star.temperatureK = k;
  } else if (what == "luminosity") {
    star.luminosity = nonNegative(key, value);
  } else {
    glm::dvec3 p(0.0);
    std::size_t at = 0;
    for (int c = 0; c < 3; ++c) {
      std::size_t comma = value.find(',', at);
      if ((c < 2) != (comma != std::string::npos)) throw Error(key + ": expected X,Y,Z, got " + excerpt(value));
      p[c] = render::parseFloat(key, value.substr(at, comma == std::string::npos ? std::string::npos : comma - at));
      if (!(std::abs(p[c]) <= 100.0)) throw Error(key + ": expected coordinates in [-100, 100], got " + excerpt(value));
      at = comma + 1;
    }
    star.position = p;
  }
  return true;
}

}  // namespace

bool setNebulaKey(Scene& scene, const std::string& key, const std::string& value) {
  static const char* const kKeys[] = {"nebula.method",     "nebula.basis",      "nebula.basis_depth", "nebula.steps",
                                      "nebula.filters",    "nebula.intensity",  "nebula.extinction",
                                      "nebula.scattering", "nebula.emission",   "nebula.ionisation",
                                      "nebula.ionisation.front_radius",         "nebula.ionisation.front_width",
                                      "nebula.light_surfaces"};
  if (setPassbandKey(scene.techniques.find<nebula::NebulaSection>(), key, value)) return true;
  bool known = !starKeyWhat(key).empty();
  for (const char* k : kKeys) known = known || key == k;
  if (!known) return false;
  auto* s = scene.techniques.find<nebula::NebulaSection>();
  if (!s) throw Error("the scene has no nebula section");
  if (setStarKey(*s, key, value)) return true;
  if (key == "nebula.method") {
    try {
      s->method = nebula::methodFromName(value);
    } catch (const Error& e) {
      throw Error(std::string("nebula.method: ") + e.what());
    }
  } else if (key == "nebula.basis") {
    s->basis = static_cast<int>(render::parseInteger(key, value, 1, nebula::kMaxBasisSize));
  } else if (key == "nebula.basis_depth") {
    const double v = render::parseNumber(key, value);
    if (!(v > 0.0 && v <= nebula::kMaxBasisDepthUm))
      throw Error(fmt::format("{}: expected a depth in (0, {:g}] µm, got {}", key, nebula::kMaxBasisDepthUm, excerpt(value)));
    s->basisDepthUm = v;
  } else if (key == "nebula.steps") {
    s->steps = static_cast<int>(render::parseInteger(key, value, 1, nebula::kMaxSteps));
  } else if (key == "nebula.filters") {
    if (value != "hubble" && value != "cie1931")
      throw Error("nebula.filters: expected hubble or cie1931, got '" + excerpt(value) + "'");
    s->model.filters = value;
  } else if (key == "nebula.intensity") {
    s->intensity = nonNegative(key, value);
  } else if (key == "nebula.extinction") {
    s->model.extinction = nonNegative(key, value);
  } else if (key == "nebula.scattering") {
    s->model.scattering = nonNegative(key, value);
  } else if (key == "nebula.ionisation") {
    if (value != "on" && value != "off") throw Error("nebula.ionisation: expected on or off, got '" + excerpt(value) + "'");
    s->model.ionisation = value == "on" ? std::optional(s->model.ionisation.value_or(nebula::IonisationModel{})) : std::nullopt;
  } else if (key == "nebula.light_surfaces") {
    if (value != "on" && value != "off") throw Error("nebula.light_surfaces: expected on or off, got '" + excerpt(value) + "'");
    s->lightSurfaces = value == "on";
  } else if (key.rfind("nebula.ionisation.", 0) == 0) {  // turns the zones on
    const bool radius = key == "nebula.ionisation.front_radius";
    const double most = radius ? nebula::kMaxFrontRadius : nebula::kMaxFrontWidth;
    const double v = render::parseNumber(key, value);  // double, as the scene loader reads it
    if (!(v > 0.0 && v <= most)) throw Error(fmt::format("{}: expected a number in (0, {}], got {}", key, most, excerpt(value)));
    nebula::IonisationModel zones = s->model.ionisation.value_or(nebula::IonisationModel{});
    (radius ? zones.frontRadius : zones.frontWidth) = v;
    s->model.ionisation = zones;
  } else {
    s->model.emission = nonNegative(key, value);
  }
  return true;
}

}  // namespace prism::viewer
