#include "imaging/png_file.h"

#include <gtest/gtest.h>

#include <fstream>

#include "core/error.h"

namespace prism::imaging {
namespace {

std::filesystem::path tempPath(const std::string& name) {
  return std::filesystem::path(::testing::TempDir()) / "prism_png" / name;
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
