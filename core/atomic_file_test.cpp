#include "core/atomic_file.h"

#include <gtest/gtest.h>

#include <sys/stat.h>

#include <algorithm>
#include <chrono>
#include <fstream>
#include <functional>
#include <sstream>
#include <string>
#include <vector>

#include "core/error.h"
#include "core/error_test_support.h"

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

// An output named through a symbolic link writes the link's target, as `cp` and `>` do: the rename
// replaced the link with a plain file and left its target's old bytes (a dangling link's target
// is made).
TEST(AtomicFile, ThroughASymbolicLinkItsTargetIsWrittenAndTheLinkKept) {
  std::filesystem::path dir = std::filesystem::path(::testing::TempDir()) / "atomic_link";
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir / "shared");
  writeFileAtomically(dir / "shared" / "result.txt", "old");
  std::filesystem::create_symlink("shared/result.txt", dir / "link.txt");
  std::filesystem::create_symlink("link.txt", dir / "link_to_link.txt");
  writeFileAtomically(dir / "link_to_link.txt", "new");
  EXPECT_TRUE(std::filesystem::is_symlink(dir / "link.txt"));
  EXPECT_TRUE(std::filesystem::is_symlink(dir / "link_to_link.txt"));
  EXPECT_EQ(slurp(dir / "shared" / "result.txt"), "new");
  std::filesystem::create_symlink(dir / "shared" / "later.txt", dir / "dangling.txt");
  writeFileAtomically(dir / "dangling.txt", "made");
  EXPECT_TRUE(std::filesystem::is_symlink(dir / "dangling.txt"));
  EXPECT_EQ(slurp(dir / "shared" / "later.txt"), "made");
  // A link to where nothing can be written names both.
  std::filesystem::create_symlink("/proc/prism/nowhere.txt", dir / "nowhere.txt");
  EXPECT_EQ(errorOf([&] { requireWritable(dir / "nowhere.txt"); }),
            (dir / "nowhere.txt").string() + " (→ /proc/prism/nowhere.txt): cannot write: No such file or directory");
  std::filesystem::create_symlink("loop_b.txt", dir / "loop_a.txt");
  std::filesystem::create_symlink("loop_a.txt", dir / "loop_b.txt");
  EXPECT_EQ(errorOf([&] { writeFileAtomically(dir / "loop_a.txt", "x"); }),
            (dir / "loop_a.txt").string() + ": cannot write: too many levels of symbolic links");
}

// A write killed between its temporary and the rename (SIGKILL) left "NAME.tmpPID" for good: a
// later write of the name removes those an hour old, never a fresh one (a live writer's, maybe on
// another machine of a cluster) or another file's.
TEST(AtomicFile, AWriteRemovesTheStaleTemporariesOfItsName) {
  std::filesystem::path dir = std::filesystem::path(::testing::TempDir()) / "atomic_stale";
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  const auto twoHoursAgo = std::filesystem::file_time_type::clock::now() - std::chrono::hours(2);
  for (const char* name : {"a.bin.tmp123", "a.bin.tmp456", "a.bin.tmpx", "b.bin.tmp123"}) {
    std::ofstream(dir / name) << "left";
    std::filesystem::last_write_time(dir / name, twoHoursAgo);
  }
  std::ofstream(dir / "a.bin.tmp789") << "being written";
  writeFileAtomically(dir / "a.bin", "whole");
  std::vector<std::string> left;
  for (const auto& entry : std::filesystem::directory_iterator(dir)) left.push_back(entry.path().filename().string());
  std::sort(left.begin(), left.end());
  EXPECT_EQ(left, (std::vector<std::string>{"a.bin", "a.bin.tmp789", "a.bin.tmpx", "b.bin.tmp123"}));
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
  // No file name: refused by both, and the folder it names is not made.
  const std::filesystem::path slash = dir / "table.bin/";
  for (const auto& write : {std::function<void()>([&] { requireWritable(slash); }),
                            std::function<void()>([&] { writeFileAtomically(slash, "x"); })}) {
    EXPECT_EQ(errorOf(write), slash.string() + ": ends in a separator, so it names a folder; give a file to write");
    EXPECT_FALSE(std::filesystem::exists(dir / "table.bin"));
  }
  EXPECT_EQ(errorOf([] { requireWritable(""); }), "an output's file name is empty");
}

// An output folder (the demo's gallery): one that is there or still to be made is accepted and
// left as it was; a file of its name, a file above it, or a place without files is refused.
TEST(RequireWritableFolder, AcceptsFoldersThereOrToBeMadeAndRefusesFiles) {
  std::filesystem::path dir = std::filesystem::path(::testing::TempDir()) / "require_writable_folder";
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  EXPECT_NO_THROW(requireWritableFolder(dir));
  EXPECT_NO_THROW(requireWritableFolder(dir / "gallery" / "new"));
  EXPECT_TRUE(std::filesystem::is_empty(dir));
  writeFileAtomically(dir / "plain", "x");
  auto message = [](const std::filesystem::path& folder) {
    try {
      requireWritableFolder(folder);
    } catch (const Error& e) {
      return std::string(e.what());
    }
    return std::string("accepted");
  };
  EXPECT_NE(message(dir / "plain").find("plain: is a file, not a folder"), std::string::npos) << message(dir / "plain");
  EXPECT_NE(message(dir / "plain" / "gallery").find("plain is not a folder"), std::string::npos);
  EXPECT_NE(message("/proc/prism-gallery").find("/proc/prism-gallery: cannot write"), std::string::npos);
  EXPECT_EQ(slurp(dir / "plain"), "x");
}

TEST(AtomicFile, APipeOrDeviceWhereTheFileGoesIsRefusedAndKept) {
  std::filesystem::path dir = std::filesystem::path(::testing::TempDir()) / "atomic_special";
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  const std::filesystem::path fifo = dir / "out.exr";
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  const std::string expected = fifo.string() + ": is not a plain file (a device, pipe or socket); Prism writes only plain files";
  for (auto write : {+[](const std::filesystem::path& p) { writeFileAtomically(p, "x"); },
                     +[](const std::filesystem::path& p) { requireWritable(p); }}) {
    try {
      write(fifo);
      ADD_FAILURE() << "a pipe was taken for a file";
    } catch (const Error& e) {
      EXPECT_EQ(std::string(e.what()), expected);
    }
    EXPECT_TRUE(std::filesystem::is_fifo(fifo));
  }
  EXPECT_THROW(requireWritable("/dev/null"), Error);  // a device, even one that takes writes
  EXPECT_TRUE(std::filesystem::is_character_file("/dev/null"));
  EXPECT_EQ(std::distance(std::filesystem::directory_iterator(dir), {}), 1);
}

TEST(RequireOtherFile, AnOutputThatIsAnInputOrAnotherOutputIsAnError) {
  std::filesystem::path dir = std::filesystem::path(::testing::TempDir()) / "atomic_other_file";
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir / "sub");
  writeFileAtomically(dir / "in.png", "input");
  std::filesystem::create_symlink(dir / "in.png", dir / "link.png");
  auto errorOf = [](const std::filesystem::path& out, const std::filesystem::path& other) {
    try {
      requireOtherFile(out, other, "the reference image");
    } catch (const Error& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  const std::filesystem::path viaDots = dir / "sub" / ".." / "in.png";
  EXPECT_EQ(errorOf(viaDots, dir / "in.png"),
            viaDots.string() + ": is also the reference image; write it to another file");
  EXPECT_NE(errorOf(dir / "link.png", dir / "in.png"), "");              // through a link
  EXPECT_NE(errorOf(dir / "new.exr", dir / "sub" / ".." / "new.exr"), "");  // two outputs, neither made yet
  EXPECT_EQ(errorOf(dir / "out.png", dir / "in.png"), "");
  EXPECT_EQ(errorOf(dir / "new.exr", dir / "new_variance.exr"), "");
  EXPECT_EQ(errorOf(dir / "out.png", ""), "");
  const std::filesystem::path here = std::filesystem::current_path();
  std::filesystem::current_path(dir);
  EXPECT_NE(errorOf("v.exr", "./v.exr"), "");  // relative, neither there yet
  std::filesystem::current_path(here);
  EXPECT_EQ(slurp(dir / "in.png"), "input");
}

}  // namespace
}  // namespace prism
