#include "viewer/scene_settings.h"

#include <algorithm>
#include <sstream>
#include <vector>

#include <fmt/format.h>

#include "core/error.h"
#include "core/json_schema.h"
#include "render/setting_keys.h"
#include "viewer/light_spectrum.h"

namespace prism::viewer {
namespace {

glm::vec3 parseVec3(const std::string& what, const std::string& text) {
  glm::vec3 v;
  std::stringstream in(text);
  std::string part;
  for (int i = 0; i < 3; ++i) {
    if (!std::getline(in, part, ',')) throw Error(fmt::format("{}: expected X,Y,Z, got \"{}\"", what, excerpt(text)));
    v[i] = render::parseFloat(what, part);
  }
  return v;
}

// light.N.spd NAME, light.N.intensity X, light.N.direction X,Y,Z, light.N.position X,Y,Z (point and
// spot lights), light.N.shadows on|off (parts: light, N, what).
void setLightKey(Scene& scene, const std::string& key, const std::vector<std::string>& parts,
                 const std::string& value) {
  if (scene.lights.empty()) throw Error(fmt::format("{}: the scene has no lights", excerpt(key)));
  auto i = static_cast<std::size_t>(
      render::parseInteger("light index", parts[1], 0, static_cast<long>(scene.lights.size()) - 1));
  Light& light = scene.lights[i];
  if (parts[2] == "spd") setLightSpd(light, value);
  else if (parts[2] == "intensity") light.intensity = render::parseFloatWithin(key, value, 0.0f, static_cast<float>(schema::kFloatInputLimit));
  else if (parts[2] == "direction") {
    glm::vec3 d = parseVec3(key, value);
    if (!(glm::length(d) > 0.0f)) throw Error(fmt::format("{}: expected a non-zero direction", excerpt(key)));
    light.direction = glm::normalize(d);
  } else if (parts[2] == "position") {
    if (light.type == LightType::Directional)
      throw Error(fmt::format("{}: light {} is directional: it has no position", excerpt(key), i));
    light.position = parseVec3(key, value);
  } else if (parts[2] == "shadows") {
    if (value != "on" && value != "off")
      throw Error(fmt::format("{}: expected on or off, got \"{}\"", excerpt(key), excerpt(value)));
    light.castsShadows = value == "on";
  } else {
    throw Error(fmt::format("unknown setting \"{}\" (light.N.spd, intensity, direction, position, shadows)", excerpt(key)));
  }
}

// An emitting material's luminance, its spectrum's shape kept (glTF's: the cd/m² of its emissive
// white); refused where it emits nothing (the scene file or the glTF gives the spectrum) and at 0
// or less (the scene file's bound).
void setEmissionLuminance(Material& m, const std::string& key, const std::string& value) {
  if (!m.emission && !m.emitsRgb())
    throw Error(fmt::format("{}: {} emits no light (what it emits is the scene file's or its glTF's)", excerpt(key),
                            excerpt(m.name)));
  const float luminance = render::parseFloatWithin(key, value, 0.0f, static_cast<float>(schema::kFloatInputLimit));
  if (!(luminance > 0.0f)) throw Error(fmt::format("{}: expected a luminance above 0, got \"{}\"", excerpt(key), excerpt(value)));
  (m.emission ? m.emission->luminance : m.emissiveLuminance) = luminance;
}

// material.NAME.base-colour R,G,B, material.NAME.roughness X, material.NAME.metallic X,
// material.NAME.emission-luminance X (cd/m², an emitting material's: its spectrum's shape kept).
void setMaterialKey(Scene& scene, const std::string& key, const std::vector<std::string>& parts,
                    const std::string& value) {
  auto it = std::find_if(scene.materials.begin(), scene.materials.end(),
                         [&](const Material& m) { return m.name == parts[1]; });
  if (it == scene.materials.end()) throw Error(fmt::format("{}: no material \"{}\"", excerpt(key), excerpt(parts[1])));
  if (it->conductor && (parts[2] == "base-colour" || parts[2] == "metallic"))
    throw Error(fmt::format("{}: {} is a conductor, whose colour and metalness are its measured n and k", excerpt(key),
                            excerpt(parts[1])));
  if (it->lambertian && parts[2] == "metallic" && render::parseFloatWithin(key, value, 0.0f, 1.0f) > 0.0f)
    throw Error(fmt::format("{}: {} is lambertian, which diffuses all of the light: metallic must be 0", excerpt(key),
                            excerpt(parts[1])));
  if (parts[2] == "base-colour") {
    const glm::vec3 c = parseVec3(key, value);
    if (glm::any(glm::lessThan(c, glm::vec3(0.0f))) || glm::any(glm::greaterThan(c, glm::vec3(1.0f))))
      throw Error(fmt::format("{}: expected R,G,B within 0–1, got \"{}\"", excerpt(key), excerpt(value)));
    it->baseColour = c;
  } else if (parts[2] == "roughness") it->roughness = render::parseFloatWithin(key, value, 0.0f, 1.0f);
  else if (parts[2] == "metallic") it->metallic = render::parseFloatWithin(key, value, 0.0f, 1.0f);
  else if (parts[2] == "emission-luminance") setEmissionLuminance(*it, key, value);
  else
    throw Error(fmt::format("unknown setting \"{}\" (material.NAME.base-colour, roughness, metallic, emission-luminance)",
                            excerpt(key)));
}

}  // namespace

bool applySceneSetting(Scene& scene, const std::string& key, const std::string& value) {
  std::vector<std::string> parts;
  std::stringstream in(key);
  for (std::string p; std::getline(in, p, '.');) parts.push_back(p);
  if (parts.size() != 3) return false;
  if (parts[0] == "light") {
    setLightKey(scene, key, parts, value);
    return true;
  }
  if (parts[0] == "material") {
    setMaterialKey(scene, key, parts, value);
    return true;
  }
  return false;
}

}  // namespace prism::viewer
