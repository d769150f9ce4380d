#include "viewer/viewer_settings.h"

#include <cmath>
#include <optional>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "core/atomic_file.h"
#include "core/error.h"
#include "core/file_extension.h"
#include "core/json_schema.h"
#include "render/setting_keys.h"

namespace prism::viewer {
namespace {

// Within ±schema::kFloatInputLimit, as a scene's camera: [1e30, 0, 0] was refused as a target
// equal to the position (its squared length overflowed float), 1e15 taken.
glm::vec3 vec3Of(const nlohmann::json& j, const std::string& where) {
  auto inRange = [](const nlohmann::json& v) {
    return v.is_number() && std::abs(v.get<double>()) <= schema::kFloatInputLimit;
  };
  if (!j.is_array() || j.size() != 3 || !inRange(j[0]) || !inRange(j[1]) || !inRange(j[2])) {
    throw Error(fmt::format("{}: expected [x, y, z], each within ±{:g}, got {}", where, schema::kFloatInputLimit,
                            excerpt(j.dump())));
  }
  return {j[0].get<float>(), j[1].get<float>(), j[2].get<float>()};
}

bool isRangeKey(std::string_view key) {
  const render::SettingKey* k = render::findFrameSettingKey(key);
  return k && k->type == render::SettingType::Range;
}

// A frame key's value as the table parses it: a string as written, a number as JSON writes it
// (a hand-written 32 or 9.5 means what "32" or "9.5" does), true and false as on and off, and
// for a range key (`range`) an array of numbers joined by commas ([380, 720] is "380,720");
// nullopt for anything else: "wavelengths": [8] is not 8.
std::optional<std::string> settingText(std::string_view key, const nlohmann::json& value) {
  if (value.is_string()) return value.get<std::string>();
  if (value.is_boolean()) return value.get<bool>() ? "on" : "off";
  if (value.is_number()) return value.dump();
  if (!value.is_array() || value.empty() || !isRangeKey(key)) return std::nullopt;
  std::string text;
  for (const nlohmann::json& element : value) {
    if (!element.is_number()) return std::nullopt;
    text += (text.empty() ? "" : ",") + element.dump();
  }
  return text;
}

}  // namespace

bool applyViewSetting(ViewSettings& view, std::string_view key, std::string_view value) {
  if (key.starts_with("right.")) {
    if (!render::applyFrameSetting(view.right, key.substr(6), value)) {
      throw Error(fmt::format("unknown setting \"{}\"", excerpt(key)));
    }
    return true;
  }
  if (render::applyFrameSetting(view.left, key, value)) return true;
  if (key != "split" && key != "heat-map") return false;
  if (value != "on" && value != "off") throw Error(fmt::format("{}: expected on or off, got \"{}\"", excerpt(key), excerpt(value)));
  (key == "split" ? view.split : view.heatMap) = value == "on";
  return true;
}

ViewSettings initialView(const render::FrameSettings& initial) {
  ViewSettings view;
  view.left = initial;
  view.right = initial;
  view.right.mode = render::RenderMode::Rgb;
  view.right.observer = "cie1931";
  return view;
}

void saveViewSettings(const std::filesystem::path& path, const ViewSettings& view, const Camera& camera) {
  requireExtension(path, ".json", "", "settings file");  // JSON named x.png was taken for an image
  nlohmann::json j;
  // Not the views' size: the window's (a loaded 9000 × 20 was saved back while 64 × 48 was drawn).
  auto windowSized = [](const std::string& key) { return key == "width" || key == "height"; };
  for (const auto& [key, value] : render::frameSettingValues(view.left))
    if (!windowSized(key)) j["left"][key] = value;
  for (const auto& [key, value] : render::frameSettingValues(view.right))
    if (!windowSized(key)) j["right"][key] = value;
  j["split"] = view.split;
  j["heat_map"] = view.heatMap;
  j["camera"] = {{"position", {camera.position.x, camera.position.y, camera.position.z}},
                 {"target", {camera.target.x, camera.target.y, camera.target.z}},
                 {"up", {camera.up.x, camera.up.y, camera.up.z}},
                 {"fov_deg", camera.verticalFovDeg}};
  writeFileAtomically(path, j.dump(2) + "\n");
}

void requireOneDisplaySpace(const ViewSettings& view, const std::filesystem::path& png) {
  if (view.split && view.right.display.colourSpace != view.left.display.colourSpace)
    throw Error(fmt::format("{}: a PNG names one display space, and the split views show {} and {}: set both alike "
                            "(display, right.display)",
                            png.string(), view.left.display.colourSpace, view.right.display.colourSpace));
}

void loadViewSettings(const std::filesystem::path& path, ViewSettings& view, Camera& camera) {
  const std::vector<unsigned char> bytes = schema::readBinaryFile(path);
  const std::string file = path.string();
  nlohmann::json j = schema::parseJson(std::string_view(reinterpret_cast<const char*>(bytes.data()), bytes.size()), file);
  if (!j.is_object()) throw Error(fmt::format("{}: not a JSON object", file));
  ViewSettings next = view;
  Camera nextCamera = camera;
  for (const auto& [key, value] : j.items()) {
    if (key == "left" || key == "right") {
      render::FrameSettings& side = key == "left" ? next.left : next.right;
      if (!value.is_object()) throw Error(fmt::format("{}: /{}: expected an object", file, excerpt(key)));
      for (const auto& [k, v] : value.items()) {
        std::optional<std::string> valueText = settingText(k, v);
        if (!valueText)
          throw Error(fmt::format("{}: /{}/{}: expected a string, a number, true or false{}, got {}", file, excerpt(key),
                                  excerpt(k), isRangeKey(k) ? ", or an array of numbers" : "", excerpt(v.dump())));
        try {
          if (!render::applyFrameSetting(side, k, *valueText)) throw Error("unknown setting");
        } catch (const Error& e) {
          throw Error(fmt::format("{}: /{}/{}: {}", file, excerpt(key), excerpt(k), e.what()));
        }
      }
      try {
        render::validate(side);
      } catch (const Error& e) {
        throw Error(fmt::format("{}: /{}: {}", file, excerpt(key), e.what()));
      }
    } else if (key == "split" || key == "heat_map") {
      if (!value.is_boolean()) throw Error(fmt::format("{}: /{}: expected true or false", file, excerpt(key)));
      (key == "split" ? next.split : next.heatMap) = value.get<bool>();
    } else if (key == "camera") {
      if (!value.is_object()) throw Error(fmt::format("{}: /camera: expected an object", file));
      for (const auto& [k, v] : value.items()) {
        std::string where = fmt::format("{}: /camera/{}", file, k);
        if (k == "position") nextCamera.position = vec3Of(v, where);
        else if (k == "target") nextCamera.target = vec3Of(v, where);
        else if (k == "up") nextCamera.up = vec3Of(v, where);
        else if (k == "fov_deg") {
          if (!(v.is_number() && v.get<double>() >= kMinCameraFovDeg && v.get<double>() < kMaxCameraFovDeg))
            throw Error(fmt::format("{}: expected degrees in [{:g}, {:g}), got {}", where, kMinCameraFovDeg, kMaxCameraFovDeg,
                                    excerpt(v.dump())));
          nextCamera.verticalFovDeg = v.get<float>();  // a scene's range: 1e-30 was taken
        } else {
          throw Error(fmt::format("{}: unknown key (allowed: position, target, up, fov_deg)", where));
        }
      }
    } else {
      throw Error(fmt::format("{}: /{}: unknown key (allowed: left, right, split, heat_map, camera)", file, excerpt(key)));
    }
  }
  glm::vec3 look = nextCamera.target - nextCamera.position;
  if (!(glm::length(look) > 0.0f) || !(glm::length(glm::cross(look, nextCamera.up)) > 1e-6f * glm::length(look))) {
    throw Error(fmt::format("{}: /camera: the target must differ from the position, and up must not be parallel "
                            "to the view", file));
  }
  for (auto [from, to] : {std::pair{&view.left, &next.left}, std::pair{&view.right, &next.right}}) {
    to->width = from->width;  // the window's, whatever a file says
    to->height = from->height;
  }
  view = next;
  camera = nextCamera;
}

}  // namespace prism::viewer
