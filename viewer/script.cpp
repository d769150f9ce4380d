#include "viewer/script.h"

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "core/error.h"
#include "render/setting_keys.h"
#include "viewer/camera_controller.h"
#include "viewer/scene_settings.h"
#include "viewer/soak.h"
#include "viewer/technique_settings.h"
#include "viewer/viewer_settings.h"

namespace prism::viewer {
namespace {

struct ScriptLine {
  int line = 0;
  std::vector<std::string> words;
};

std::vector<ScriptLine> readScript(const std::filesystem::path& path) {
  std::ifstream in(path);
  if (!in) throw Error(fmt::format("{}: cannot read the script", path.string()));
  std::vector<ScriptLine> lines;
  std::string text;
  for (int n = 1; std::getline(in, text); ++n) {
    if (std::size_t hash = text.find('#'); hash != std::string::npos) text.resize(hash);
    std::istringstream words(text);
    ScriptLine line{n, {}};
    for (std::string w; words >> w;) line.words.push_back(w);
    if (!line.words.empty()) lines.push_back(std::move(line));
  }
  return lines;
}

void set(Viewer& viewer, const std::string& key, const std::string& value) {
  Changes& changes = viewer.changes();
  if (applyViewSetting(viewer.view(), key, value)) {
    changes.settings = true;
    return;
  }
  if (key == "fov") {
    viewer.camera().setFieldOfView(render::parseFloatWithin(key, value, kMinFieldOfViewDeg, kMaxFieldOfViewDeg));
    changes.camera = true;
    return;
  }
  Scene& scene = viewer.scene();
  for (TechniqueSetKey set : techniqueSetKeys()) {
    if (set(scene, key, value)) {
      changes.scene = true;
      return;
    }
  }
  if (applySceneSetting(scene, key, value)) {
    changes.scene = true;
    return;
  }
  throw Error(fmt::format("unknown setting \"{}\" (the frame keys of `prism settings --keys`, right.KEY, split, "
                          "heat-map, fov, light.N.*, material.NAME.*, water.type, water.depth, sky.*, prt.*)", excerpt(key)));
}

void execute(Viewer& viewer, const std::vector<std::string>& w) {
  auto need = [&](std::size_t n) {
    if (w.size() != n + 1) throw Error(fmt::format("{} takes {} argument{}", w[0], n, n == 1 ? "" : "s"));
  };
  const std::string& verb = w[0];
  if (verb == "set") {
    need(2);
    set(viewer, w[1], w[2]);
    if (viewer.changes().settings) {  // a bad value should fail here, at its line
      render::validate(viewer.view().left);
      render::validate(viewer.view().right);
    }
  } else if (verb == "frames") {
    need(1);
    long n = render::parseInteger("frames", w[1], 0, 1000000);
    for (long i = 0; i < n; ++i) viewer.frame();
    if (!viewer.renderError().empty()) throw Error(viewer.renderError());
  } else if (verb == "resize") {
    need(2);
    viewer.resize(static_cast<int>(render::parseInteger("width", w[1], 16, 8192)),
                  static_cast<int>(render::parseInteger("height", w[2], 16, 8192)));
  } else if (verb == "orbit") {
    need(2);
    viewer.camera().orbit(render::parseFloat("yaw", w[1]) * kDegrees, render::parseFloat("pitch", w[2]) * kDegrees);
    viewer.changes().camera = true;
  } else if (verb == "screenshot") {
    need(1);
    viewer.screenshot(w[1], true);
  } else if (verb == "save-settings") {
    need(1);
    saveViewSettings(w[1], viewer.view(), viewer.camera().camera());
  } else if (verb == "load-settings") {
    need(1);
    viewer.loadSettings(w[1]);
  } else if (verb == "heat-map-stats") {
    need(0);
    const ViewSettings& view = viewer.view();
    if (!(view.split && view.heatMap) || viewer.compositor().heatMap().id() == 0) {
      throw Error("no heat map yet (set split on, heat-map on, frames N)");
    }
    const imaging::DifferenceStats& stats = viewer.compositor().heatMapStats();
    fmt::print("heat map: mean {:.3f} p95 {:.3f} max {:.3f}\n", stats.meanDeltaE, stats.p95DeltaE, stats.maxDeltaE);
    std::fflush(stdout);
  } else if (verb == "reload-shaders") {
    need(0);
    viewer.reloadShaders();
  } else if (verb == "soak") {
    if (w.size() != 2 && w.size() != 3) throw Error("soak takes FRAMES and optionally MAX-GROWTH-MB");
    soak(viewer, static_cast<int>(render::parseInteger("soak", w[1], 1, 1000000)),
         w.size() == 3 ? std::optional<double>(render::parseFloat("soak's memory bound", w[2])) : std::nullopt);
  } else {
    throw Error(fmt::format("unknown command \"{}\" (set, frames, resize, orbit, screenshot, save-settings, "
                            "load-settings, reload-shaders, soak, heat-map-stats)", excerpt(verb)));
  }
}

}  // namespace

int runScript(Viewer& viewer, const std::filesystem::path& path) {
  std::vector<ScriptLine> lines = readScript(path);
  viewer.frame();
  for (const ScriptLine& line : lines) {
    try {
      execute(viewer, line.words);
    } catch (const std::exception& e) {
      fmt::print(stderr, "prism: error: {}:{}: {}\n", path.string(), line.line, e.what());
      return 1;
    }
  }
  return 0;
}

}  // namespace prism::viewer
