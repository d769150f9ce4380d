// `prism merge` of a split PRT bake: the file it writes is found by the renderer by its name
// alone (cacheDir/prt/transfer-KEY.bin), so a name keyed for another bake is refused.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <regex>
#include <string>

#include "app/cli_test_support.h"

namespace prism::app::test {
namespace {

TEST(Merge, APrtBakeIsNamedForItsOwnKey) {
  const std::filesystem::path dir = std::filesystem::path(::testing::TempDir()) / "merge_prt_names";
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  const std::filesystem::path scene = dir / "tiny.json";
  std::ofstream(scene) << R"({"camera": {"position": [0, 1, 3], "target": [0, 0, 0]},
    "materials": {"m": {"base_colour": [0.6, 0.3, 0.2]}},
    "objects": [{"sphere": {"centre": [0, 0, 0], "radius": 0.5, "segments": 8}, "material": "m", "technique": "prt"}],
    "prt": {"environment": {"illuminant": "A", "shape": "uniform", "luminance": 100}, "samples": 8}})";
  std::string parts;
  for (int i = 0; i < 2; ++i) {
    const std::filesystem::path part = dir / ("part" + std::to_string(i));
    Result baked = run("prt bake " + scene.string() + " --part " + std::to_string(i) + "/2 -o " + part.string());
    ASSERT_EQ(baked.exitCode, 0) << baked.err;
    parts += " " + part.string();
  }
  // Under a name of its own: written, and the name the renderer reads said.
  Result named = run("merge" + parts + " -o " + (dir / "rock.bin").string());
  ASSERT_EQ(named.exitCode, 0) << named.err;
  std::smatch key;
  ASSERT_TRUE(std::regex_search(named.out, key, std::regex("key ([0-9a-f]{16})"))) << named.out;
  const std::string cacheName = "transfer-" + key[1].str() + ".bin";
  EXPECT_NE(named.out.find("the renderer reads it as " + cacheName + " in its cache's prt folder"), std::string::npos)
      << named.out;
  // Under the cache's name for it: written, nothing more said.
  Result own = run("merge" + parts + " -o " + (dir / cacheName).string());
  ASSERT_EQ(own.exitCode, 0) << own.err;
  EXPECT_EQ(own.out.find("the renderer reads it"), std::string::npos) << own.out;
  EXPECT_EQ(slurp(dir / cacheName), slurp(dir / "rock.bin"));
  // Under the cache's name for another bake: refused, nothing written (the renderer read it,
  // refused it for its key and baked again, unsaid).
  const std::string other = key[1].str() == "0123456789abcdef" ? "transfer-fedcba9876543210.bin" : "transfer-0123456789abcdef.bin";
  Result wrong = run("merge" + parts + " -o " + (dir / other).string());
  EXPECT_EQ(wrong.exitCode, 1);
  EXPECT_EQ(wrong.err, "prism: error: " + (dir / other).string() + ": named for another bake; these parts are the bake of key " + key[1].str() +
                           ", which the renderer reads as " + cacheName + "\n");
  EXPECT_FALSE(std::filesystem::exists(dir / other));
  // A bake is no image: a display option is refused, not ignored.
  Result shown = run("merge" + parts + " --tonemap reinhard -o " + (dir / "shown.bin").string());
  EXPECT_EQ(shown.exitCode, 1);
  EXPECT_EQ(shown.err, "prism: error: --tonemap: parts of a PRT bake make no image to display\n");
}

}  // namespace
}  // namespace prism::app::test
