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
      {"short.hdr", header + "-Y 100 +X 1000\n" + std::string("\x02\x02\x03\xe8\x80\x01", 6),
       ": truncated: the data ends in scan line 0 of 100 (1000 × 100)"},
      // Flat (uncompressed) lines of 12 bytes: the first whole, the data ends in the second (it
      // said the first whatever the length).
      {"flat_short.hdr", header + "-Y 2 +X 3\n" + std::string(20, 'a'),
       ": truncated: the data ends in scan line 1 of 2 (3 × 2)"},
      {"flat_shorter.hdr", header + "-Y 2 +X 3\n" + std::string(11, 'a'),
       ": truncated: the data ends in scan line 0 of 2 (3 × 2)"},
      // A compressed line (8 pixels, each component one run), then a flat one: stb reads the whole
      // image flat from there, 64 bytes where 32 are left (it was taken as one line short of whole,
      // and stb read past the end).
      {"flat_after_compressed.hdr",
       header + "-Y 2 +X 8\n" + std::string("\x02\x02\x00\x08\x88\x01\x88\x01\x88\x01\x88\x80", 12) +
           std::string(32, 'a'),
       ": truncated: scan line 1 has no run-length marker, so the whole image is read flat from it, and that data "
       "ends in its scan line 1 of 2 (8 × 2)"},
      {"flat_trailing.hdr", header + "-Y 2 +X 3\n" + std::string(29, 'a'),
       ": 5 bytes after the image's last scan line (3 × 2)"},
      {"compressed_trailing.hdr",
       header + "-Y 1 +X 8\n" + std::string("\x02\x02\x00\x08\x88\x01\x88\x01\x88\x01\x88\x80\n", 13),
       ": 1 byte after the image's last scan line (8 × 1)"},
      {"zero_run.hdr", header + "-Y 1 +X 8\n" + std::string("\x02\x02\x00\x08\x00", 5),
       ": scan line 0: a run of 0 pixels where 8 are left"},
      {"long_run.hdr", header + "-Y 1 +X 8\n" + std::string("\x02\x02\x00\x08\xff\x01", 6),
       ": scan line 0: a run of 127 pixels where 8 are left"},
      {"no_format.hdr", "#?RADIANCE\n\n-Y 1 +X 1\nabcd", ": the header has no FORMAT=32-bit_rle_rgbe line"},
      // stb reads a header line up to its first NUL: this one ends the header there.
      {"nul_line.hdr", header.substr(0, header.size() - 1) + std::string("\0x\n", 3) + "-Y 10000 +X 16384\n\n-Y 1 +X 1\nabcd",
       ": truncated: the data ends in scan line 0 of 10000 (16384 × 10000)"},
  };
  for (const Case& c : cases) {
    std::filesystem::path p = writeBytes(c.name, c.bytes);
    EXPECT_EQ(readError(p), p.string() + c.error);
    std::filesystem::remove(p);
  }
  EXPECT_EQ(readError(hdrPath("missing.hdr")), hdrPath("missing.hdr").string() + ": cannot open: no such file");
}

}  // namespace
}  // namespace prism::imaging
