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

}  // namespace
}  // namespace prism
