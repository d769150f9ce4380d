// Scripts are read and checked before anything renders (no window needed here): quotes keep
// spaces, comments stop at #, and a bad line anywhere is "FILE:LINE: what".
#include "viewer/script.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "core/error.h"
#include "scene/scene.h"

namespace prism::viewer {
namespace {

std::filesystem::path scriptFile(const std::string& name, const std::string& text) {
  const std::filesystem::path p = std::filesystem::path(::testing::TempDir()) / name;
  std::ofstream(p) << text;
  return p;
}

std::string loadError(const std::filesystem::path& p) {
  try {
    loadScript(p);
  } catch (const Error& e) {
    return e.what();
  }
  return "";
}

TEST(Script, QuotesKeepSpacesAndCommentsStopAtHash) {
  const Script s = loadScript(scriptFile("quoted.txt", "# a comment\nset light.0.spd \"nist:Cool White FL\"  # lamp\n\n"
                                                       "set observer \"Canon EOS 5D Mark II (rawtoaces)\"\nframes 2\n"
                                                       "screenshot \"a b#c.png\"\n"));
  ASSERT_EQ(s.lines.size(), 4u);
  EXPECT_EQ(s.lines[0].line, 2);
  EXPECT_EQ(s.lines[0].words, (std::vector<std::string>{"set", "light.0.spd", "nist:Cool White FL"}));
  EXPECT_EQ(s.lines[1].words[2], "Canon EOS 5D Mark II (rawtoaces)");
  EXPECT_EQ(s.lines[3].words[1], "a b#c.png");
}

// A typo on the last line used to fail only after every command before it had run (screenshots
// written, frames rendered); a folder ran nothing and exited 0.
TEST(Script, EveryLineIsCheckedBeforeAnythingRuns) {
  const std::filesystem::path late = scriptFile("late.txt", "screenshot a1.png\nframes 3\nbogus\n");
  EXPECT_EQ(loadError(late), late.string() + ":3: unknown command \"bogus\" (set, frames, resize, orbit, screenshot, "
                                             "save-settings, load-settings, reload-shaders, soak, heat-map-stats)");
  const std::filesystem::path counts = scriptFile("counts.txt", "frames 2\nresize 8 600\n");
  EXPECT_EQ(loadError(counts).rfind(counts.string() + ":2: width: expected", 0), 0u) << loadError(counts);
  const std::filesystem::path arity = scriptFile("arity.txt", "set fov\n");
  EXPECT_EQ(loadError(arity), arity.string() + ":1: set takes 2 arguments");
  const std::filesystem::path quote = scriptFile("quote.txt", "set light.0.spd \"nist:Cool White FL\n");
  EXPECT_EQ(loadError(quote), quote.string() + ":1: a quote is not closed");
  const std::filesystem::path png = scriptFile("png.txt", "frames 1\nsave-settings s.png\n");  // wrote JSON as .png
  EXPECT_EQ(loadError(png), png.string() + ":2: s.png: the settings file is written as a .json file");
  const std::filesystem::path orbit = scriptFile("orbit.txt", "orbit left 10\n");
  EXPECT_NE(loadError(orbit).find(":1: yaw: expected"), std::string::npos) << loadError(orbit);
  // A negative soak bound passed, ran the soak and failed it; a .jpg screenshot and `set width`
  // (the views take the window's size, so it did nothing) were found only at their lines.
  const std::filesystem::path soak = scriptFile("soak.txt", "soak 1 -5\n");
  EXPECT_NE(loadError(soak).find(":1: soak's memory bound: expected a number within 0"), std::string::npos)
      << loadError(soak);
  const std::filesystem::path jpg = scriptFile("jpg.txt", "frames 1\nscreenshot x.jpg\n");
  EXPECT_EQ(loadError(jpg), jpg.string() + ":2: x.jpg: a screenshot is a .png or an .exr");
  const std::filesystem::path width = scriptFile("width.txt", "set right.width 4000\n");
  EXPECT_EQ(loadError(width),
            width.string() + ":1: right.width: the views take the window's size; `resize WIDTH HEIGHT` sets it");
  const std::filesystem::path dir = std::filesystem::path(::testing::TempDir());
  EXPECT_EQ(loadError(dir), dir.string() + ": is a folder, not a script");
  EXPECT_EQ(loadError(dir / "missing.txt"), (dir / "missing.txt").string() + ": cannot read the script");
}

// The rehearsal (rehearseScript), which runs before the window's first frame: a bad value, a light
// the scene lacks, a missing settings file, a screenshot over the scene's file are found at their
// lines, before a screenshot above them is written; a settings file the script saves is loaded
// as saved, and an orbit turns the camera that a later settings file completes.
std::string rehearsalError(const std::string& name, const std::string& text, const Scene& scene) {
  const std::filesystem::path path = scriptFile(name, text);
  try {
    rehearseScript(loadScript(path), ViewSettings{}, CameraController(Camera{}), scene);
  } catch (const Error& e) {
    const std::string what = e.what();
    return what.substr(path.string().size());
  }
  return "rehearsed";
}

TEST(Script, TheRehearsalFindsBadLinesBeforeAnythingRuns) {
  Scene scene;
  scene.file = std::filesystem::path(::testing::TempDir()) / "scene.json";
  Light sun;
  sun.direction = {0.0f, -1.0f, 0.0f};
  scene.lights = {sun};
  const std::string dir = ::testing::TempDir();
  const std::string bogus = rehearsalError("r1.txt", "screenshot " + dir + "/a.png\nset mode bogus\n", scene);
  EXPECT_EQ(bogus.rfind(":2: mode: expected", 0), 0u) << bogus;
  EXPECT_FALSE(std::filesystem::exists(dir + "/a.png"));
  EXPECT_EQ(rehearsalError("r2.txt", "set light.3.intensity 5\n", scene).rfind(":1: light index: expected", 0), 0u);
  EXPECT_EQ(rehearsalError("r3.txt", "frames 1\nload-settings " + dir + "/none.json\n", scene).rfind(":2: ", 0), 0u);
  EXPECT_EQ(rehearsalError("r4.txt", "save-settings " + scene.file.string() + "\n", scene),
            ":1: " + scene.file.string() + ": is also the scene file; write it to another file");
  // Saved as jakob-hanika under CIE 1964, changed to RGB, loaded back: CIE 1964 holds again (the
  // rehearsal kept RGB and refused it), and through another spelling of the same path.
  const std::string saved = dir + "/saved_settings.json";
  std::filesystem::remove(saved);
  EXPECT_EQ(rehearsalError("r5.txt",
                           "set mode jakob-hanika\nset observer cie1964\nsave-settings " + saved +
                               "\nset observer cie1931\nset mode rgb\nload-settings " + dir + "/./saved_settings.json" +
                               "\nset observer cie1964\n",
                           scene),
            "rehearsed");
  EXPECT_FALSE(std::filesystem::exists(saved)) << "the rehearsal writes nothing";
  // A PNG of a split window names one display space: halves encoded for two are refused there
  // (the file was tagged as the left's), an EXR (the left view alone) or one space is taken.
  const std::string twoSpaces = "set split on\nset right.display rec2020\nscreenshot " + dir + "/split.png\n";
  EXPECT_EQ(rehearsalError("r6.txt", twoSpaces, scene).rfind(":3: " + dir + "/split.png: a PNG names one display space", 0),
            0u)
      << rehearsalError("r6.txt", twoSpaces, scene);
  EXPECT_EQ(rehearsalError("r7.txt", "set split on\nset right.display rec2020\nscreenshot " + dir + "/split.exr\n", scene),
            "rehearsed");
  EXPECT_EQ(rehearsalError("r8.txt",
                           "set split on\nset display rec2020\nset right.display rec2020\nscreenshot " + dir +
                               "/split.png\n",
                           scene),
            "rehearsed");
}

}  // namespace
}  // namespace prism::viewer
