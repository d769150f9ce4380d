// One settings vocabulary, held to it: every key of render/setting_keys.h's table, set to its
// example value on the command line (`prism settings --KEY=VALUE`), by the viewer script's
// `set KEY VALUE` and `set right.KEY VALUE` (applyViewSetting, what the script runs) and in a
// settings file (loadViewSettings, which leaves the views' size to the window), must give the
// same frame settings, compared by the table's printed values. A key one of them drops, renames
// or parses differently fails here.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "app/cli_test_support.h"
#include "render/setting_keys.h"
#include "viewer/viewer_settings.h"

namespace prism {
namespace {

using Values = std::vector<std::pair<std::string, std::string>>;

// `prism settings ARGS`' "KEY VALUE" lines.
Values fromCommandLine(const std::string& args) {
  app::test::Result r = app::test::run("settings " + args);
  EXPECT_EQ(r.exitCode, 0) << args << ": " << r.err;
  Values values;
  std::istringstream lines(r.out);
  for (std::string line; std::getline(lines, line);) {
    std::size_t space = line.find(' ');
    values.emplace_back(line.substr(0, space), space == std::string::npos ? "" : line.substr(space + 1));
  }
  return values;
}

Values fromSettingsFile(const std::string& key, const std::string& value) {
  std::filesystem::path file = std::filesystem::path(::testing::TempDir()) / ("parity_" + key + ".json");
  std::ofstream(file) << "{\"left\": {\"" << key << "\": \"" << value << "\"}}";
  viewer::ViewSettings view;
  Camera camera;
  viewer::loadViewSettings(file, view, camera);
  return render::frameSettingValues(view.left);
}

TEST(SettingsParity, EveryKeyMeansTheSameOnTheCommandLineInTheScriptAndInSettingsFiles) {
  const Values defaults = render::frameSettingValues(render::FrameSettings{});
  EXPECT_EQ(fromCommandLine(""), defaults);
  for (const render::SettingKey& key : render::frameSettingKeys()) {
    SCOPED_TRACE(key.name + " " + key.example);
    Values expected = defaults;
    for (auto& [name, value] : expected) {
      if (name == key.name) value = key.example;
    }
    ASSERT_NE(expected, defaults) << "the example must differ from the default, or a dropped key would pass";

    EXPECT_EQ(fromCommandLine("--" + key.name + "=" + key.example), expected) << "the command line";

    viewer::ViewSettings view;
    ASSERT_TRUE(viewer::applyViewSetting(view, key.name, key.example));
    EXPECT_EQ(render::frameSettingValues(view.left), expected) << "the script's set";
    ASSERT_TRUE(viewer::applyViewSetting(view, "right." + key.name, key.example));
    EXPECT_EQ(render::frameSettingValues(view.right), expected) << "the script's set right.KEY";

    // Every key but the views' size, which is the window's (the script refuses `set width` too).
    const bool windowSized = key.name == "width" || key.name == "height";
    EXPECT_EQ(fromSettingsFile(key.name, key.example), windowSized ? defaults : expected) << "a settings file";
  }
}

// Every key, but those a command has no use for: bench sets the mode per configuration, and
// `wavelengths optimise` fits for a count, a range and an observer alone.
TEST(SettingsParity, TheHelpListsEveryKey) {
  for (const char* command : {"render", "view", "bench", "settings", "wavelengths optimise"}) {
    app::test::Result r = app::test::run(std::string(command) + " --help");
    ASSERT_EQ(r.exitCode, 0) << command;
    for (const render::SettingKey& key : render::frameSettingKeys()) {
      const bool used = command == std::string("bench")                  ? key.name != "mode"
                        : command == std::string("wavelengths optimise") ? key.name == "wavelengths" ||
                                                                               key.name == "range" || key.name == "observer"
                                                                         : true;
      const bool listed = r.out.find("--" + key.name + " ") != std::string::npos ||  // an option: "--range MIN,MAX"
                          r.out.find("--" + key.name + "{") != std::string::npos;    // a switch: "--gizmos{on}"
      EXPECT_EQ(listed, used) << command << " --" << key.name;
    }
  }
}

}  // namespace
}  // namespace prism
