#include "spectral/rgb_to_spectrum_cache.h"

#include <gtest/gtest.h>

#include <unistd.h>

#include <cstdlib>
#include <fstream>
#include <string>

namespace prism {
namespace {

class CacheTest : public ::testing::Test {
 protected:
  void SetUp() override {
    // One folder per test and process: ctest runs these tests in parallel processes.
    const auto* test = ::testing::UnitTest::GetInstance()->current_test_info();
    mDir = std::filesystem::path(::testing::TempDir()) /
           ("prism_cache_test_" + std::string(test->name()) + "_" + std::to_string(getpid()));
    std::filesystem::remove_all(mDir);
    setenv("PRISM_CACHE_DIR", mDir.c_str(), 1);
  }
  void TearDown() override {
    unsetenv("PRISM_CACHE_DIR");
    std::filesystem::remove_all(mDir);
  }
  std::filesystem::path mDir;
};

TEST_F(CacheTest, BuildsOnceThenLoads) {
  int progressCalls = 0;
  auto count = [&](std::size_t, std::size_t) { ++progressCalls; };
  RgbToSpectrumTable first = cachedRgbToSpectrumTable("srgb", 6, count);
  EXPECT_GT(progressCalls, 0);
  std::filesystem::path path = rgbToSpectrumCachePath("srgb", 6);
  EXPECT_EQ(path.parent_path(), mDir);
  EXPECT_TRUE(std::filesystem::is_regular_file(path));

  progressCalls = 0;
  RgbToSpectrumTable second = cachedRgbToSpectrumTable("srgb", 6, count);
  EXPECT_EQ(progressCalls, 0) << "a valid cache entry must not be rebuilt";
  EXPECT_TRUE(std::equal(first.data().begin(), first.data().end(), second.data().begin()));
}

TEST_F(CacheTest, RebuildsADamagedEntry) {
  RgbToSpectrumTable first = cachedRgbToSpectrumTable("srgb", 6);
  std::filesystem::path path = rgbToSpectrumCachePath("srgb", 6);
  std::filesystem::resize_file(path, std::filesystem::file_size(path) / 2);
  int progressCalls = 0;
  RgbToSpectrumTable rebuilt =
      cachedRgbToSpectrumTable("srgb", 6, [&](std::size_t, std::size_t) { ++progressCalls; });
  EXPECT_GT(progressCalls, 0);
  EXPECT_TRUE(std::equal(first.data().begin(), first.data().end(), rebuilt.data().begin()));
  EXPECT_NO_THROW(RgbToSpectrumTable::load(path));
}

TEST_F(CacheTest, KeysDifferByGamutAndResolution) {
  EXPECT_NE(rgbToSpectrumCachePath("srgb", 6), rgbToSpectrumCachePath("srgb", 7));
  EXPECT_NE(rgbToSpectrumCachePath("srgb", 6), rgbToSpectrumCachePath("rec2020", 6));
}

}  // namespace
}  // namespace prism
