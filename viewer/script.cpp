#include "viewer/script.h"

#include <algorithm>
#include <cstdio>
#include <map>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "core/atomic_file.h"
#include "core/error.h"
#include "core/file_extension.h"
#include "core/json_schema.h"
#include "render/frame_data.h"
#include "render/setting_keys.h"
#include "viewer/camera_controller.h"
#include "viewer/scene_settings.h"
#include "viewer/soak.h"
#include "viewer/technique_settings.h"
#include "viewer/viewer.h"
#include "viewer/viewer_loop.h"
#include "viewer/viewer_settings.h"

namespace prism::viewer {
namespace {

// The words of one line: separated by spaces, "…" one word with its spaces, # a comment.
std::vector<std::string> wordsOf(const std::string& text) {
  std::vector<std::string> words;
  std::size_t i = 0;
  while (i < text.size()) {
    const char c = text[i];
    if (c == '#') break;
    if (c == ' ' || c == '\t' || c == '\r') {
      ++i;
      continue;
    }
    std::string word;
    if (c == '"') {
      const std::size_t close = text.find('"', i + 1);
      if (close == std::string::npos) throw Error("a quote is not closed");
      word = text.substr(i + 1, close - i - 1);
      i = close + 1;
    } else {
      const std::size_t end = text.find_first_of(" \t\r#\"", i);
      word = text.substr(i, end == std::string::npos ? std::string::npos : end - i);
      i = end == std::string::npos ? text.size() : end;
    }
    words.push_back(std::move(word));
  }
  return words;
}

constexpr float kMaxSoakGrowthMb = 1e6f;  // a terabyte: any bound a soak could mean

// What a command's arguments must be, checked before the script runs; execute() relies on it.
void checkCommand(const std::vector<std::string>& w) {
  const std::string& verb = w[0];
  auto need = [&](std::size_t n) {
    if (w.size() != n + 1) throw Error(fmt::format("{} takes {} argument{}", verb, n, n == 1 ? "" : "s"));
  };
  if (verb == "set" || verb == "orbit") {
    need(2);
    if (verb == "set" && (w[1] == "width" || w[1] == "height" || w[1] == "right.width" || w[1] == "right.height"))
      throw Error(fmt::format("{}: the views take the window's size; `resize WIDTH HEIGHT` sets it", w[1]));
    if (verb == "orbit") {
      render::parseFloat("yaw", w[1]);
      render::parseFloat("pitch", w[2]);
    }
  } else if (verb == "frames") {
    need(1);
    render::parseInteger("frames", w[1], 0, 1000000);
  } else if (verb == "resize") {
    need(2);
    render::parseInteger("width", w[1], kMinWindowSide, kMaxWindowSide);
    render::parseInteger("height", w[2], kMinWindowSide, kMaxWindowSide);
  } else if (verb == "screenshot" || verb == "save-settings" || verb == "load-settings") {
    need(1);
    const std::string extension = lowercaseExtension(w[1]);
    if (verb == "screenshot" && extension != ".png" && extension != ".exr")
      throw Error(fmt::format("{}: a screenshot is a .png or an .exr", excerpt(w[1])));
    if (verb == "save-settings") requireExtension(w[1], ".json", "", "settings file");
  } else if (verb == "heat-map-stats" || verb == "reload-shaders") {
    need(0);
  } else if (verb == "soak") {
    if (w.size() != 2 && w.size() != 3) throw Error("soak takes FRAMES and optionally MAX-GROWTH-MB");
    render::parseInteger("soak", w[1], 1, 1000000);
    if (w.size() == 3) render::parseFloatWithin("soak's memory bound", w[2], 0.0f, kMaxSoakGrowthMb);
  } else {
    throw Error(fmt::format("unknown command \"{}\" (set, frames, resize, orbit, screenshot, save-settings, "
                            "load-settings, reload-shaders, soak, heat-map-stats)", excerpt(verb)));
  }
}

// What `set` and `load-settings` change: the viewer's own state, or the rehearsal's copy of it.
struct Settable {
  ViewSettings& view;
  CameraController& camera;
  Scene& scene;
  Changes& changes;
};

void set(const Settable& target, const std::string& key, const std::string& value) {
  Changes& changes = target.changes;
  // A combination the renderer refuses (rgb-prt under a camera) fails here, at its line.
  auto requireShown = [&target] {
    for (const render::FrameSettings* side : {&target.view.left, &target.view.right})
      render::requireTechniquesShow(target.scene, *side);
  };
  if (applyViewSetting(target.view, key, value)) {
    changes.settings = true;
    render::validate(target.view.left);  // a bad combination fails here, at its line
    render::validate(target.view.right);
    requireShown();
    return;
  }
  if (key == "fov") {
    target.camera.setFieldOfView(render::parseFloatWithin(key, value, kMinFieldOfViewDeg, kMaxFieldOfViewDeg));
    changes.camera = true;
    return;
  }
  Scene& scene = target.scene;
  for (TechniqueSetKey set : techniqueSetKeys()) {
    if (set(scene, key, value)) {
      changes.scene = true;
      requireShown();
      return;
    }
  }
  if (applySceneSetting(scene, key, value)) {
    changes.scene = true;
    return;
  }
  throw Error(fmt::format("unknown setting \"{}\" (the frame keys of `prism settings --keys`, right.KEY, split, "
                          "heat-map, fov, light.N.*, material.NAME.*, water.type, water.depth, sky.*, prt.*, nebula.*)",
                          excerpt(key)));
}

// One checked command (checkCommand).
void execute(Viewer& viewer, const std::vector<std::string>& w) {
  const std::string& verb = w[0];
  if (verb == "set") {
    set({viewer.view(), viewer.camera(), viewer.scene(), viewer.changes()}, w[1], w[2]);
  } else if (verb == "frames") {
    long n = render::parseInteger("frames", w[1], 0, 1000000);
    for (long i = 0; i < n; ++i) viewer.frame();
    if (!viewer.renderError().empty()) throw Error(viewer.renderError());
  } else if (verb == "resize") {
    viewer.resize(static_cast<int>(render::parseInteger("width", w[1], kMinWindowSide, kMaxWindowSide)),
                  static_cast<int>(render::parseInteger("height", w[2], kMinWindowSide, kMaxWindowSide)));
  } else if (verb == "orbit") {
    viewer.camera().orbit(render::parseFloat("yaw", w[1]) * kDegrees, render::parseFloat("pitch", w[2]) * kDegrees);
    viewer.changes().camera = true;
  } else if (verb == "screenshot") {
    viewer.screenshot(w[1], true);
  } else if (verb == "save-settings") {
    viewer.saveSettings(w[1]);
  } else if (verb == "load-settings") {
    viewer.loadSettings(w[1]);
  } else if (verb == "heat-map-stats") {
    const ViewSettings& view = viewer.view();
    if (!(view.split && view.heatMap) || viewer.compositor().heatMap().id() == 0) {
      // The reason the heat map went off, if it did: the script had asked for it as this says.
      const std::string& why = viewer.compositor().heatMapError();
      throw Error(why.empty() ? std::string("no heat map yet (set split on, heat-map on, frames N)")
                              : "no heat map: " + why);
    }
    const imaging::DifferenceStats& stats = viewer.compositor().heatMapStats();
    fmt::print("heat map: mean {:.3f} p95 {:.3f} max {:.3f}\n", stats.meanDeltaE, stats.p95DeltaE, stats.maxDeltaE);
    std::fflush(stdout);
  } else if (verb == "reload-shaders") {
    viewer.reloadShaders();
  } else if (verb == "soak") {
    soak(viewer, static_cast<int>(render::parseInteger("soak", w[1], 1, 1000000)),
         w.size() == 3 ? std::optional<double>(
                             render::parseFloatWithin("soak's memory bound", w[2], 0.0f, kMaxSoakGrowthMb))
                       : std::nullopt);
  }
}

}  // namespace

Script loadScript(const std::filesystem::path& path) {
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec)) throw Error(fmt::format("{}: is a folder, not a script", path.string()));
  if (!std::filesystem::exists(path, ec)) throw Error(fmt::format("{}: cannot read the script", path.string()));
  const std::vector<unsigned char> bytes = schema::readBinaryFile(path);
  std::istringstream in(std::string(bytes.begin(), bytes.end()));
  Script script{path, {}};
  std::string text;
  for (int n = 1; std::getline(in, text); ++n) {
    try {
      ScriptLine line{n, wordsOf(text)};
      if (line.words.empty()) continue;
      checkCommand(line.words);
      script.lines.push_back(std::move(line));
    } catch (const Error& e) {
      throw Error(fmt::format("{}:{}: {}", path.string(), n, e.what()));
    }
  }
  return script;
}

void rehearseScript(const Script& script, ViewSettings view, CameraController camera, Scene scene) {
  Changes changes;
  // What each save-settings line wrote, by the file's resolved path: a later load-settings of it
  // takes that, as the run will, not the file as it is now (missing, or an older one).
  std::map<std::filesystem::path, std::pair<ViewSettings, Camera>> saved;
  auto resolved = [](const std::string& path) {
    std::error_code ec;
    std::filesystem::path p = std::filesystem::weakly_canonical(path, ec);
    return ec ? std::filesystem::path(path) : p;
  };
  for (const ScriptLine& line : script.lines) {
    const std::vector<std::string>& w = line.words;
    try {
      if (w[0] == "screenshot" || w[0] == "save-settings") {
        requireWritable(w[1]);
        requireOtherFile(w[1], script.path, "the script");
        requireNotSceneInput(w[1], scene);
        if (w[0] == "screenshot" && lowercaseExtension(w[1]) == ".png") requireOneDisplaySpace(view, w[1]);
        if (w[0] == "save-settings") saved[resolved(w[1])] = {view, camera.camera()};
      } else if (w[0] == "set") {
        set({view, camera, scene, changes}, w[1], w[2]);
      } else if (w[0] == "orbit") {  // a settings file giving part of the camera is checked with the rest
        camera.orbit(render::parseFloat("yaw", w[1]) * kDegrees, render::parseFloat("pitch", w[2]) * kDegrees);
      } else if (w[0] == "load-settings") {
        std::error_code ec;
        if (auto it = saved.find(resolved(w[1])); it != saved.end()) {
          view = it->second.first;
          camera = CameraController(it->second.second);
        } else if (!std::filesystem::exists(w[1], ec) || std::filesystem::is_regular_file(w[1], ec)) {
          Camera loaded = camera.camera();  // a pipe is left to the run, which alone may read it
          loadViewSettings(w[1], view, loaded);
          camera = CameraController(loaded);
        }
      }
    } catch (const std::exception& e) {
      throw Error(fmt::format("{}:{}: {}", script.path.string(), line.line, e.what()));
    }
  }
}

int runScript(Viewer& viewer, const Script& script) {
  try {
    rehearseScript(script, viewer.view(), viewer.camera(), viewer.scene());
  } catch (const Error& e) {
    fmt::print(stderr, "prism: error: {}\n", e.what());
    return 1;
  }
  viewer.frame();
  for (const ScriptLine& line : script.lines) {
    try {
      execute(viewer, line.words);
    } catch (const std::exception& e) {
      fmt::print(stderr, "prism: error: {}:{}: {}\n", script.path.string(), line.line, e.what());
      return 1;
    }
  }
  return 0;
}

}  // namespace prism::viewer
