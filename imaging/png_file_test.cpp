#include "imaging/png_file.h"

#include <gtest/gtest.h>

#include <fstream>
#include <iterator>

#include "core/error.h"

namespace prism::imaging {
namespace {

std::filesystem::path tempPath(const std::string& name) {
  return std::filesystem::path(::testing::TempDir()) / "prism_png" / name;
}

// CRC-32 (ISO 3309, as PNG's chunks carry it), bit by bit, as four big-endian bytes: written out
// here so that the test does not share zlib's.
std::string bigEndianCrc32(const std::string& bytes) {
  std::uint32_t crc = 0xFFFFFFFFu;
  for (unsigned char byte : bytes) {
    crc ^= byte;
    for (int bit = 0; bit < 8; ++bit) crc = (crc >> 1) ^ (0xEDB88320u & (0u - (crc & 1u)));
  }
  crc ^= 0xFFFFFFFFu;
  return {static_cast<char>(crc >> 24), static_cast<char>(crc >> 16), static_cast<char>(crc >> 8), static_cast<char>(crc)};
}

TEST(PngImage, FillsClippedRectangles) {
  PngImage image(8, 4, {1, 2, 3});
  image.fillRect(6, 2, 10, 10, {200, 100, 50});
  EXPECT_EQ(image.pixel(0, 0).b, 3);
  EXPECT_EQ(image.pixel(7, 3).r, 200);
  EXPECT_EQ(image.pixel(5, 3).r, 1);
}

TEST(PngImage, DrawsText) {
  PngImage image(64, 16, {0, 0, 0});
  image.drawText(1, 1, "A1", {255, 255, 255}, 1);
  int lit = 0;
  for (int y = 0; y < 16; ++y)
    for (int x = 0; x < 64; ++x) lit += image.pixel(x, y).r == 255;
  EXPECT_GT(lit, 10);
  EXPECT_GT(textWidth("A1", 2), textWidth("A1", 1));
}

TEST(PngImage, WritesAPngFile) {
  std::filesystem::path p = tempPath("tiny.png");
  PngImage(3, 2, {9, 9, 9}).write(p);
  std::ifstream in(p, std::ios::binary);
  char signature[8] = {};
  in.read(signature, 8);
  EXPECT_EQ(std::string(signature + 1, 3), "PNG");
}

TEST(PngImage, UnwritablePathIsAnError) {
  EXPECT_THROW(PngImage(1, 1, {}).write("/proc/prism_cannot_write.png"), prism::Error);
}

TEST(PngImage, ReadsBackWhatItWrote) {
  PngImage opaque(5, 3, {10, 20, 30});
  opaque.setPixel(4, 2, {250, 128, 0});
  opaque.write(tempPath("opaque.png"));
  PngImage back = readPng8(tempPath("opaque.png"));
  ASSERT_EQ(back.width(), 5);
  ASSERT_EQ(back.height(), 3);
  EXPECT_EQ(back.rgba(), opaque.rgba());

  PngImage translucent(2, 2, {1, 2, 3});
  translucent.setPixel(1, 0, {7, 8, 9}, 100);
  translucent.write(tempPath("translucent.png"));
  back = readPng8(tempPath("translucent.png"));
  EXPECT_EQ(back.rgba(), translucent.rgba());
  EXPECT_EQ(back.alpha(1, 0), 100);
}

// A P3 or Rec.2020 image says so in a cICP chunk (H.273 primaries, transfer, RGB, full range),
// which reading gives back; an untagged file is sRGB. A space no display encodes is refused, and so
// is a file whose cICP names codes Prism does not decode, with the file's name.
TEST(PngImage, CarriesItsColourSpaceInCicp) {
  struct Case {
    const char* space;
    char primaries, transfer;
  };
  for (const Case& c : {Case{"srgb", 1, 13}, Case{"display-p3", 12, 13}, Case{"rec2020", 9, 14}}) {
    PngImage image(4, 2, {200, 100, 50});
    image.setColourSpace(c.space);
    const std::filesystem::path p = tempPath(std::string(c.space) + ".png");
    image.write(p);
    std::ifstream in(p, std::ios::binary);
    const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    const std::string chunk = std::string("\0\0\0\4cICP", 8) + std::string{c.primaries, c.transfer, 0, 1};
    EXPECT_EQ(bytes.substr(33, 12), chunk) << c.space;
    EXPECT_EQ(bytes.substr(45, 4), bigEndianCrc32(chunk.substr(4))) << c.space << ": the CRC of type and data";
    const PngImage back = readPng8(p);
    EXPECT_EQ(back.colourSpace(), c.space);
    EXPECT_EQ(back.rgba(), image.rgba());
  }
  EXPECT_THROW(PngImage(1, 1, {}).setColourSpace("acescg"), Error);
  PngImage p3(1, 1, {});
  p3.setColourSpace("p3");  // the display settings' other name for it
  EXPECT_EQ(p3.colourSpace(), "display-p3");

  const std::filesystem::path p = tempPath("display-p3.png"), odd = tempPath("pq.png");
  std::string bytes;
  {
    std::ifstream in(p, std::ios::binary);
    bytes.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
  }
  bytes[42] = 16;  // transfer: SMPTE ST 2084 (PQ); the chunk's CRC is left as it was (not checked)
  std::ofstream(odd, std::ios::binary) << bytes;
  try {
    readPng8(odd);
    FAIL() << "expected an Error";
  } catch (const Error& e) {
    EXPECT_EQ(std::string(e.what()).rfind(odd.string() + ": cICP names colour primaries 12, transfer 16", 0), 0u) << e.what();
  }
}

TEST(PngImage, ReadErrorsNameTheFile) {
  std::filesystem::path missing = tempPath("no_such_file.png");
  try {
    readPng8(missing);
    FAIL() << "expected an Error";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find(missing.string()), std::string::npos) << e.what();
  }
  std::filesystem::path text = tempPath("text.png");
  std::filesystem::create_directories(text.parent_path());
  std::ofstream(text) << "not a PNG";
  try {
    readPng8(text);
    FAIL() << "expected an Error";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find(text.string()), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace prism::imaging
