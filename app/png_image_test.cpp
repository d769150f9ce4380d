#include "app/png_image.h"

#include <gtest/gtest.h>

#include <fstream>

#include "spectral/error.h"

namespace prism::app {
namespace {

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
}

TEST(PngImage, WritesAPngFile) {
  std::filesystem::path p = std::filesystem::path(::testing::TempDir()) / "png" / "tiny.png";
  PngImage(3, 2, {9, 9, 9}).write(p);
  std::ifstream in(p, std::ios::binary);
  char signature[8] = {};
  in.read(signature, 8);
  EXPECT_EQ(std::string(signature + 1, 3), "PNG");
}

TEST(PngImage, UnwritablePathIsAnError) {
  EXPECT_THROW(PngImage(1, 1, {}).write("/proc/prism_cannot_write.png"), prism::Error);
}

}  // namespace
}  // namespace prism::app
