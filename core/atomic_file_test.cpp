#include "core/atomic_file.h"

#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include "core/error.h"

namespace prism {
namespace {

std::string slurp(const std::filesystem::path& p) {
  std::ifstream in(p);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

TEST(AtomicFile, WritesReplacesAndLeavesNoTemporary) {
  std::filesystem::path dir = std::filesystem::path(::testing::TempDir()) / "atomic" / "nested";
  std::filesystem::remove_all(dir);
  writeFileAtomically(dir / "a.txt", "first");
  writeFileAtomically(dir / "a.txt", "second");
  EXPECT_EQ(slurp(dir / "a.txt"), "second");
  int files = 0;
  for (const auto& entry : std::filesystem::directory_iterator(dir)) files += entry.is_regular_file();
  EXPECT_EQ(files, 1);
}

TEST(AtomicFile, UnwritablePlaceIsAnErrorAndTargetIsUntouched) {
  std::filesystem::path dir = std::filesystem::path(::testing::TempDir()) / "atomic_dir_target";
  std::filesystem::create_directories(dir / "child");
  // Renaming a file over a non-empty directory fails: the directory must survive intact.
  EXPECT_THROW(writeFileAtomically(dir, "x"), Error);
  EXPECT_TRUE(std::filesystem::is_directory(dir / "child"));
  for (const auto& entry : std::filesystem::directory_iterator(dir.parent_path()))
    EXPECT_EQ(entry.path().string().find("atomic_dir_target.tmp"), std::string::npos);
}

TEST(RequireWritable, AcceptsNewFilesAndFoldersToBeMadeAndLeavesNothing) {
  std::filesystem::path dir = std::filesystem::path(::testing::TempDir()) / "require_writable";
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  EXPECT_NO_THROW(requireWritable(dir / "out.png"));
  EXPECT_NO_THROW(requireWritable(dir / "not" / "yet" / "made" / "out.png"));
  EXPECT_TRUE(std::filesystem::is_empty(dir));
}

TEST(RequireWritable, RefusesAFolderAFileAsAFolderAndAPlaceWithoutFiles) {
  std::filesystem::path dir = std::filesystem::path(::testing::TempDir()) / "require_writable_bad";
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  writeFileAtomically(dir / "plain", "x");
  EXPECT_THROW(requireWritable(dir), Error);
  try {
    requireWritable(dir / "plain" / "out.png");
    FAIL() << "a file used as a folder was accepted";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("plain is not a folder"), std::string::npos) << e.what();
  }
  // /proc takes no new files, even from root.
  EXPECT_THROW(requireWritable("/proc/prism-out.png"), Error);
}

}  // namespace
}  // namespace prism
