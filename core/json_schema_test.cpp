// What a scene's numbers read as float (Node::numberF, vec2, vec3) must hold as floats, and what
// its integers (Node::integer) must hold as ints, said in the error; where a file that leaves its
// root is said to go (confinedFile); and which values a message says `--set` put there.
#include "core/json_schema.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "core/error.h"

namespace prism::schema {
namespace {

std::string errorOf(const nlohmann::json& value, const Range& range) {
  const Document document{"scene.json", {}};
  try {
    Node(value, "/x", document).numberF(range);
  } catch (const Error& e) {
    return e.what();
  }
  return "read";
}

TEST(NumberAsFloat, IsInItsRangeOnceAFloat) {
  // 1e-300 > 0 as a double, 0 as a float: a sphere of that radius aborted every command.
  EXPECT_EQ(errorOf(1e-300, Range::above(0.0)),
            "scene.json: /x: expected a number in (0, 1e+12], got 1e-300 (0 as a float, the renderer's precision)");
  // A bound no float holds is compared as a float too: float(0.7) < 0.7, yet 0.7 is in [0.7, 1].
  EXPECT_EQ(errorOf(0.7, Range::closed(0.7, 1.0)), "read");
  EXPECT_EQ(errorOf(0.69, Range::closed(0.7, 1.0)), "scene.json: /x: expected a number in [0.7, 1], got 0.69");
}

std::string integerErrorOf(const nlohmann::json& value, const Range& range) {
  const Document document{"scene.json", {}};
  try {
    return std::to_string(Node(value, "/x", document).integer(range));
  } catch (const Error& e) {
    return e.what();
  }
}

// At the pointer --set named and anywhere inside it; not at a key whose name it only begins.
TEST(Document, SaysWhatTheCommandLineSet) {
  Document document{"scene.json", {"/lights/1"}};
  EXPECT_TRUE(document.isSetOnCommandLine("/lights/1"));
  EXPECT_TRUE(document.isSetOnCommandLine("/lights/1/intensity"));
  EXPECT_FALSE(document.isSetOnCommandLine("/lights/10"));
  EXPECT_FALSE(document.isSetOnCommandLine("/lights"));
  try {
    Node(nlohmann::json("bright"), "/lights/1/intensity", document).number();
    ADD_FAILURE() << "no error";
  } catch (const Error& e) {
    EXPECT_EQ(std::string(e.what()), "scene.json: /lights/1/intensity (set on the command line): expected a finite number, got \"bright\"");
  }
}

TEST(Integer, IsInItsRangeAndInts) {
  // A nebula's seed past int's range read "expected an integer >= 0, got 2147483648".
  EXPECT_EQ(integerErrorOf(2147483648LL, Range::atLeast(0)),
            "scene.json: /x: expected an integer in [0, 2147483647], got 2147483648");
  EXPECT_EQ(integerErrorOf(2147483647LL, Range::atLeast(0)), "2147483647");
  EXPECT_EQ(integerErrorOf(-1, Range::atLeast(0)), "scene.json: /x: expected an integer in [0, 2147483647], got -1");
  EXPECT_EQ(integerErrorOf(-2147483648LL, Range::any()), "-2147483648");
  EXPECT_EQ(integerErrorOf(17, Range::closed(1, 16)), "scene.json: /x: expected an integer in [1, 16], got 17");
  EXPECT_EQ(integerErrorOf(1.5, Range::closed(1, 16)), "scene.json: /x: expected an integer in [1, 16], got 1.5");
}

// A file that resolves outside its root names the root resolved, as the file is: a scene in the
// working folder, its root ".", read "outside .".
TEST(ConfinedFile, NamesTheRootResolved) {
  namespace fs = std::filesystem;
  const fs::path root = fs::path(::testing::TempDir()) / "confined" / "scene";
  fs::remove_all(root.parent_path());
  fs::create_directories(root);
  std::ofstream(root.parent_path() / "outside.png") << "x";
  fs::create_directory_symlink(root.parent_path(), root / "escape");
  const fs::path relativeRoot = fs::relative(root);
  ASSERT_TRUE(relativeRoot.is_relative());
  try {
    confinedFile(relativeRoot, relativeRoot, "escape/outside.png");
    ADD_FAILURE() << "no Error";
  } catch (const Error& e) {
    EXPECT_EQ(std::string(e.what()), "'escape/outside.png' resolves to " + fs::weakly_canonical(root.parent_path() / "outside.png").string() +
                                         ", outside " + fs::weakly_canonical(root).string());
  }
}

}  // namespace
}  // namespace prism::schema
