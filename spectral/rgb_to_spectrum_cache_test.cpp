#include "spectral/rgb_to_spectrum_cache.h"

#include <gtest/gtest.h>

#include <unistd.h>

#include <cstdlib>
#include <algorithm>
#include <fstream>
#include <string>

#include "core/error.h"

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

// A folder where the entry belongs cannot be replaced (writeFileAtomically never replaces one):
// an Error naming it, not the stream's failure on reading a folder (it was `prism: internal
// error`, exit 70), and the folder left as it was.
TEST_F(CacheTest, AFolderWhereTheEntryBelongsIsAnError) {
  const std::filesystem::path path = rgbToSpectrumCachePath("srgb", 6);
  std::filesystem::create_directories(path / "inside");
  try {
    cachedRgbToSpectrumTable("srgb", 6);
    FAIL() << "a folder in the table's place was accepted";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find(path.string() + ": is a folder where the cache keeps the upsampling table"),
              std::string::npos)
        << e.what();
  }
  EXPECT_TRUE(std::filesystem::is_directory(path / "inside"));
  EXPECT_THROW(RgbToSpectrumTable::load(path), Error);
}

// A table consistent with its checksum but whose coefficients are not the fits of their nodes
// (forged, or written by a broken build) is caught at load, said so in one line, and rebuilt.
TEST_F(CacheTest, RebuildsAnEntryWhoseCoefficientsDoNotReproduceTheirColours) {
  RgbToSpectrumTable first = cachedRgbToSpectrumTable("srgb", 6);
  RgbToSpectrumTable forged = first;
  for (int block = 0; block < 3; ++block)
    for (int z = 0; z < 6; ++z)
      for (int y = 0; y < 6; ++y)
        for (int x = 0; x < 6; ++x) forged.setCoefficients(block, z, y, x, first.coefficients(block, z, y, x) * 1.5f);
  const std::filesystem::path path = rgbToSpectrumCachePath("srgb", 6);
  forged.save(path);
  ASSERT_NO_THROW(RgbToSpectrumTable::load(path));  // the checksum holds

  ::testing::internal::CaptureStderr();
  RgbToSpectrumTable rebuilt = cachedRgbToSpectrumTable("srgb", 6);
  const std::string said = ::testing::internal::GetCapturedStderr();
  EXPECT_TRUE(std::equal(first.data().begin(), first.data().end(), rebuilt.data().begin()));
  EXPECT_NE(said.find("prism: cache entry " + path.string() + " is damaged (node ("), std::string::npos) << said;
  EXPECT_NE(said.find("): rebuilding\n"), std::string::npos) << said;
  EXPECT_EQ(said.find('\n'), said.size() - 1) << said;

  ::testing::internal::CaptureStderr();
  cachedRgbToSpectrumTable("srgb", 6);
  EXPECT_EQ(::testing::internal::GetCapturedStderr(), "") << "the rebuilt entry is trusted";
}

// The header records the hash of the inputs the table was made from, under the checksum: a sound
// table moved under another key (another optimiser version, observer or white) is not trusted.
TEST_F(CacheTest, RebuildsAnEntryMadeFromOtherInputs) {
  RgbToSpectrumTable first = cachedRgbToSpectrumTable("srgb", 6);
  EXPECT_NE(first.inputsHash(), 0u);
  RgbToSpectrumTable moved = first;
  moved.setInputsHash(first.inputsHash() ^ 0x5a5a5a5au);
  const std::filesystem::path path = rgbToSpectrumCachePath("srgb", 6);
  moved.save(path);
  EXPECT_EQ(RgbToSpectrumTable::load(path).inputsHash(), moved.inputsHash());

  ::testing::internal::CaptureStderr();
  RgbToSpectrumTable rebuilt = cachedRgbToSpectrumTable("srgb", 6);
  const std::string said = ::testing::internal::GetCapturedStderr();
  EXPECT_EQ(rebuilt.inputsHash(), first.inputsHash());
  EXPECT_NE(said.find("is damaged (made from other inputs: hash "), std::string::npos) << said;
  EXPECT_EQ(said.find('\n'), said.size() - 1) << said;
}

TEST_F(CacheTest, KeysDifferByGamutAndResolution) {
  EXPECT_NE(rgbToSpectrumCachePath("srgb", 6), rgbToSpectrumCachePath("srgb", 7));
  EXPECT_NE(rgbToSpectrumCachePath("srgb", 6), rgbToSpectrumCachePath("rec2020", 6));
}

}  // namespace
}  // namespace prism
