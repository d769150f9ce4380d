#include "viewer/viewer_settings.h"

#include <charconv>
#include <cmath>
#include <fstream>
#include <sstream>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "core/atomic_file.h"
#include "spectral/colour_space.h"
#include "core/error.h"

namespace prism::viewer {
namespace {

std::string strategyName(SamplingStrategy s) {
  switch (s) {
    case SamplingStrategy::Uniform: return "uniform";
    case SamplingStrategy::Stratified: return "stratified";
    case SamplingStrategy::Rotated: return "rotated";
    case SamplingStrategy::Importance: return "importance";
  }
  return "uniform";
}

std::string adaptationName(Adaptation a) {
  switch (a) {
    case Adaptation::Bradford: return "bradford";
    case Adaptation::Cat02: return "cat02";
    case Adaptation::VonKries: return "von-kries";
  }
  return "bradford";
}

const char* toneMapName(render::ToneMap t) {
  return t == render::ToneMap::None ? "none" : t == render::ToneMap::Reinhard ? "reinhard" : "aces";
}

glm::vec3 vec3Of(const nlohmann::json& j, const std::string& where) {
  if (!j.is_array() || j.size() != 3 || !j[0].is_number() || !j[1].is_number() || !j[2].is_number()) {
    throw Error(fmt::format("{}: expected [x, y, z], got {}", where, j.dump()));
  }
  return {j[0].get<float>(), j[1].get<float>(), j[2].get<float>()};
}

}  // namespace

double parseNumber(std::string_view what, std::string_view text) {
  double v = 0.0;
  auto r = std::from_chars(text.data(), text.data() + text.size(), v);
  if (r.ec != std::errc() || r.ptr != text.data() + text.size() || !std::isfinite(v)) {
    throw Error(fmt::format("{}: expected a number, got \"{}\"", what, text));
  }
  return v;
}

long parseInteger(std::string_view what, std::string_view text, long min, long max) {
  long v = 0;
  auto r = std::from_chars(text.data(), text.data() + text.size(), v);
  if (r.ec != std::errc() || r.ptr != text.data() + text.size() || v < min || v > max) {
    throw Error(fmt::format("{}: expected a whole number within {}–{}, got \"{}\"", what, min, max, text));
  }
  return v;
}

float parseFloat(std::string_view what, std::string_view text) {
  return static_cast<float>(parseNumber(what, text));
}

bool applyFrameSetting(render::FrameSettings& s, std::string_view key, std::string_view value) {
  std::string v(value);
  if (key == "mode") s.mode = render::renderModeFromName(v);
  else if (key == "wavelengths") s.sampling.count = static_cast<int>(parseInteger(key, v, 0, 100000));
  else if (key == "range") {
    std::size_t comma = v.find(',');
    if (comma == std::string::npos) throw Error(fmt::format("range: expected MIN,MAX in nm, got \"{}\"", v));
    s.sampling.minNm = parseNumber(key, std::string_view(v).substr(0, comma));
    s.sampling.maxNm = parseNumber(key, std::string_view(v).substr(comma + 1));
  } else if (key == "strategy") s.sampling.strategy = samplingStrategyFromName(v);
  else if (key == "observer") s.observer = v;
  else if (key == "lookup") {
    if (v != "manual" && v != "filtered") throw Error(fmt::format("lookup: expected manual or filtered, got \"{}\"", v));
    s.lookup = v == "manual" ? render::UpsamplingLookup::Manual : render::UpsamplingLookup::Filtered;
  } else if (key == "gbuffer") {
    if (v != "rgb" && v != "coefficients") throw Error(fmt::format("gbuffer: expected rgb or coefficients, got \"{}\"", v));
    s.gbufferAlbedo = v == "rgb" ? render::GBufferAlbedo::Rgb : render::GBufferAlbedo::Coefficients;
  } else if (key == "tonemap") s.toneMap = render::toneMapFromName(v);
  else if (key == "display") s.display = v;
  else if (key == "white-balance") s.whiteBalance = v;
  else if (key == "adaptation") s.adaptation = adaptationFromName(v);
  else if (key == "ev") s.ev100 = v == "scene" ? std::nullopt : std::optional<float>(static_cast<float>(parseNumber(key, v)));
  else if (key == "shadow-map-size") s.shadowMapSize = static_cast<int>(parseInteger(key, v, 0, 100000));
  else return false;
  return true;
}

std::map<std::string, std::string> frameSettingValues(const render::FrameSettings& s) {
  return {{"mode", std::string(render::renderModeName(s.mode))},
          {"wavelengths", std::to_string(s.sampling.count)},
          {"range", fmt::format("{:g},{:g}", s.sampling.minNm, s.sampling.maxNm)},
          {"strategy", strategyName(s.sampling.strategy)},
          {"observer", s.observer},
          {"lookup", s.lookup == render::UpsamplingLookup::Manual ? "manual" : "filtered"},
          {"gbuffer", s.gbufferAlbedo == render::GBufferAlbedo::Rgb ? "rgb" : "coefficients"},
          {"tonemap", toneMapName(s.toneMap)},
          {"display", s.display},
          {"white-balance", s.whiteBalance},
          {"adaptation", adaptationName(s.adaptation)},
          {"ev", s.ev100 ? fmt::format("{:g}", *s.ev100) : "scene"},
          {"shadow-map-size", std::to_string(s.shadowMapSize)}};
}

void saveViewSettings(const std::filesystem::path& path, const ViewSettings& view, const Camera& camera) {
  nlohmann::json j;
  j["left"] = frameSettingValues(view.left);
  j["right"] = frameSettingValues(view.right);
  j["split"] = view.split;
  j["heat_map"] = view.heatMap;
  j["camera"] = {{"position", {camera.position.x, camera.position.y, camera.position.z}},
                 {"target", {camera.target.x, camera.target.y, camera.target.z}},
                 {"up", {camera.up.x, camera.up.y, camera.up.z}},
                 {"fov_deg", camera.verticalFovDeg}};
  writeFileAtomically(path, j.dump(2) + "\n");
}

void loadViewSettings(const std::filesystem::path& path, ViewSettings& view, Camera& camera) {
  std::ifstream in(path);
  if (!in) throw Error(fmt::format("{}: cannot read the settings file", path.string()));
  std::stringstream text;
  text << in.rdbuf();
  nlohmann::json j = nlohmann::json::parse(text.str(), nullptr, false);
  const std::string file = path.string();
  if (j.is_discarded() || !j.is_object()) throw Error(fmt::format("{}: not a JSON object", file));
  ViewSettings next = view;
  Camera nextCamera = camera;
  for (const auto& [key, value] : j.items()) {
    if (key == "left" || key == "right") {
      render::FrameSettings& side = key == "left" ? next.left : next.right;
      if (!value.is_object()) throw Error(fmt::format("{}: /{}: expected an object", file, key));
      for (const auto& [k, v] : value.items()) {
        if (!v.is_string()) throw Error(fmt::format("{}: /{}/{}: expected a string, got {}", file, key, k, v.dump()));
        try {
          if (!applyFrameSetting(side, k, v.get<std::string>())) throw Error("unknown setting");
        } catch (const Error& e) {
          throw Error(fmt::format("{}: /{}/{}: {}", file, key, k, e.what()));
        }
      }
      try {
        render::validate(side);
      } catch (const Error& e) {
        throw Error(fmt::format("{}: /{}: {}", file, key, e.what()));
      }
    } else if (key == "split" || key == "heat_map") {
      if (!value.is_boolean()) throw Error(fmt::format("{}: /{}: expected true or false", file, key));
      (key == "split" ? next.split : next.heatMap) = value.get<bool>();
    } else if (key == "camera") {
      if (!value.is_object()) throw Error(fmt::format("{}: /camera: expected an object", file));
      for (const auto& [k, v] : value.items()) {
        std::string where = fmt::format("{}: /camera/{}", file, k);
        if (k == "position") nextCamera.position = vec3Of(v, where);
        else if (k == "target") nextCamera.target = vec3Of(v, where);
        else if (k == "up") nextCamera.up = vec3Of(v, where);
        else if (k == "fov_deg" && v.is_number() && v.get<float>() > 0.0f && v.get<float>() < 180.0f)
          nextCamera.verticalFovDeg = v.get<float>();
        else throw Error(fmt::format("{}: unknown key or bad value {}", where, v.dump()));
      }
    } else {
      throw Error(fmt::format("{}: /{}: unknown key (allowed: left, right, split, heat_map, camera)", file, key));
    }
  }
  glm::vec3 look = nextCamera.target - nextCamera.position;
  if (!(glm::length(look) > 0.0f) || !(glm::length(glm::cross(look, nextCamera.up)) > 1e-6f * glm::length(look))) {
    throw Error(fmt::format("{}: /camera: the target must differ from the position, and up must not be parallel "
                            "to the view", file));
  }
  view = next;
  camera = nextCamera;
}

}  // namespace prism::viewer
