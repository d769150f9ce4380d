#include "imaging/radiance_hdr.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <string>

#include "core/error_test_support.h"

namespace prism::imaging {
namespace {

// Per process, so that the release and sanitizer runs side by side do not share files.
std::filesystem::path hdrPath(const std::string& name) {
  return std::filesystem::path(::testing::TempDir()) / (std::to_string(::getpid()) + "_" + name);
}

std::filesystem::path writeBytes(const std::string& name, const std::string& bytes) {
  std::filesystem::path p = hdrPath(name);
  std::ofstream(p, std::ios::binary) << bytes;
  return p;
}

std::string readError(const std::filesystem::path& p) {
  return errorOf([&] { readRadianceHdr(p); });
}

TEST(RadianceHdr, RoundTripsWithinRgbePrecision) {
  // 9 wide (run-length encoded lines) and 3 wide (flat lines), over sixteen stops.
  for (int width : {9, 3}) {
    FloatImage image(width, 4, 3);
    for (int y = 0; y < image.height; ++y)
      for (int x = 0; x < image.width; ++x)
        for (int c = 0; c < 3; ++c)
          image.at(x, y, c) = std::ldexp(0.3f + 0.2f * static_cast<float>(c), x + 3 * y - 8);
    std::filesystem::path p = hdrPath("round_trip_" + std::to_string(width) + ".hdr");
    writeRadianceHdr(p, image);
    FloatImage back = readRadianceHdr(p);
    ASSERT_EQ(back.width, image.width);
    ASSERT_EQ(back.height, image.height);
    ASSERT_EQ(back.channels, 3);
    for (int y = 0; y < image.height; ++y) {
      for (int x = 0; x < image.width; ++x) {
        float largest = std::max({image.at(x, y, 0), image.at(x, y, 1), image.at(x, y, 2)});
        // A shared 8-bit exponent leaves each channel 8 bits of the largest's scale.
        for (int c = 0; c < 3; ++c)
          EXPECT_NEAR(back.at(x, y, c), image.at(x, y, c), largest / 128.0f) << x << "," << y << "," << c;
      }
    }
    std::filesystem::remove(p);
  }
}

TEST(RadianceHdr, NegativeValuesAreWrittenAsZero) {
  FloatImage image(8, 1, 3, 1.0f);
  image.at(2, 0, 1) = -5.0f;
  std::filesystem::path p = hdrPath("negative.hdr");
  writeRadianceHdr(p, image);
  FloatImage back = readRadianceHdr(p);
  EXPECT_EQ(back.at(2, 0, 1), 0.0f);
  EXPECT_NEAR(back.at(2, 0, 0), 1.0f, 1.0f / 128.0f);
  std::filesystem::remove(p);
}

TEST(RadianceHdr, BadFilesAreOneLineErrors) {
  const std::string header = "#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n";
  struct Case {
    std::string name, bytes, error;
  };
  const Case cases[] = {
      {"png.hdr", "\x89PNG\r\n\x1a\n", ": not a Radiance .hdr file (no #?RADIANCE signature)"},
      {"endless.hdr", "#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n", ": truncated: the header has no end (a blank line)"},
      {"xyze.hdr", "#?RADIANCE\nFORMAT=32-bit_rle_xyze\n\n-Y 1 +X 1\nabcd",
       ": FORMAT=32-bit_rle_xyze: Prism reads RGBE only (FORMAT=32-bit_rle_rgbe)"},
      {"no_resolution.hdr", header, ": truncated: no resolution line after the header"},
      {"flipped.hdr", header + "+Y 1 +X 1\nabcd", ": resolution line '+Y 1 +X 1': Prism reads '-Y HEIGHT +X WIDTH' only"},
      {"huge.hdr", header + "-Y 20000 +X 4\n", ": an image of 4 × 20000 pixels; Prism reads 1 to 16384 on each side"},
      {"short.hdr", header + "-Y 100 +X 1000\n" + std::string(10, '\2'),
       ": truncated: a 1000 × 100 image needs at least 6800 bytes of pixels, it has 10"},
  };
  for (const Case& c : cases) {
    std::filesystem::path p = writeBytes(c.name, c.bytes);
    EXPECT_EQ(readError(p), p.string() + c.error);
    std::filesystem::remove(p);
  }
  EXPECT_EQ(readError(hdrPath("missing.hdr")), hdrPath("missing.hdr").string() + ": cannot open: No such file or directory");
}

TEST(RadianceHdr, CorruptRunsAreRefusedByTheDecoder) {
  // A well-formed header whose scan lines claim more pixels than the line holds.
  std::string bytes = "#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y 1 +X 8\n";
  bytes += std::string("\2\2\0\x08", 4);
  for (int c = 0; c < 4; ++c) bytes += std::string("\xff\1", 2);  // runs of 127 in an 8-pixel line
  std::filesystem::path p = writeBytes("corrupt.hdr", bytes);
  std::string error = readError(p);
  EXPECT_TRUE(error.starts_with(p.string() + ": not a readable .hdr image: ")) << error;
  EXPECT_EQ(error.find('\n'), std::string::npos);
  std::filesystem::remove(p);
}

}  // namespace
}  // namespace prism::imaging
