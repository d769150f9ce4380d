// Scripts are read and checked before anything renders (no window needed here): quotes keep
// spaces, comments stop at #, and a bad line anywhere is "FILE:LINE: what".
#include "viewer/script.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "core/error.h"

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

}  // namespace
}  // namespace prism::viewer
