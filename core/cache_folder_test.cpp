#include "core/cache_folder.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <fstream>
#include <string>
#include <vector>

#include "core/error.h"

namespace prism {
namespace {

std::filesystem::path freshFolder(const std::string& name) {
  const std::filesystem::path dir = std::filesystem::path(::testing::TempDir()) / name;
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

std::vector<std::string> names(const std::filesystem::path& dir) {
  std::vector<std::string> out;
  for (const auto& e : std::filesystem::directory_iterator(dir)) out.push_back(e.path().filename().string());
  std::sort(out.begin(), out.end());
  return out;
}

// Entries "e0.bin" (oldest) … of `bytes` each, a minute apart, and files the cache did not name:
// another extension, another prefix, a key that is no hex number.
void entries(const std::filesystem::path& dir, int count, std::size_t bytes) {
  const auto now = std::filesystem::file_time_type::clock::now();
  for (int i = 0; i < count; ++i) {
    const std::filesystem::path p = dir / ("e" + std::to_string(i) + ".bin");
    std::ofstream(p) << std::string(bytes, 'x');
    std::filesystem::last_write_time(p, now - std::chrono::minutes(count - i));
  }
  for (const char* other : {"old.txt", "mine.bin", "ezz.bin"}) {
    std::ofstream(dir / other) << "not an entry";
    std::filesystem::last_write_time(dir / other, now - std::chrono::hours(9));
  }
}

TEST(CacheFolder, PruningKeepsTheNewestWithinBothBounds) {
  const std::filesystem::path dir = freshFolder("cache_prune");
  entries(dir, 5, 100);
  pruneCacheFolder(dir, "e", ".bin", 3, 1000);
  EXPECT_EQ(names(dir), (std::vector<std::string>{"e2.bin", "e3.bin", "e4.bin", "ezz.bin", "mine.bin", "old.txt"}));
  touchCacheEntry(dir / "e2.bin");  // read: the least recently used is e3 now
  pruneCacheFolder(dir, "e", ".bin", 10, 250);  // 250 bytes: two of 100
  EXPECT_EQ(names(dir), (std::vector<std::string>{"e2.bin", "e4.bin", "ezz.bin", "mine.bin", "old.txt"}));
  pruneCacheFolder(dir, "e", ".bin", 10, 10);  // the newest stays, whatever its size
  EXPECT_EQ(names(dir), (std::vector<std::string>{"e2.bin", "ezz.bin", "mine.bin", "old.txt"}));
}

TEST(CacheFolder, AFolderWhereAnEntryGoesIsRefused) {
  const std::filesystem::path dir = freshFolder("cache_entry_folder");
  EXPECT_NO_THROW(requireNoFolderAtEntry(dir / "entry.bin", "a PRT transfer"));  // none there yet
  std::filesystem::create_directories(dir / "entry.bin");
  try {
    requireNoFolderAtEntry(dir / "entry.bin", "a PRT transfer");
    FAIL() << "expected an Error";
  } catch (const Error& e) {
    EXPECT_EQ(std::string(e.what()), (dir / "entry.bin").string() + ": is a folder where the cache keeps a PRT transfer; remove it");
  }
}

}  // namespace
}  // namespace prism
