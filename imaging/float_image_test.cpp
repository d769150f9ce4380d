#include "imaging/float_image.h"

#include <cmath>
#include <limits>
#include <string>

#include <gtest/gtest.h>

#include "core/error.h"

namespace prism::imaging {
namespace {

TEST(NonFinitePixels, FiniteImageHasNone) {
  FloatImage image(4, 3, 3, 1e30f);
  NonFinitePixels found = nonFinitePixels(image);
  EXPECT_EQ(found.count, 0u);
  EXPECT_EQ(found.firstX, -1);
}

TEST(NonFinitePixels, CountsPixelsNotValuesAndNamesTheFirstInRowMajorOrder) {
  FloatImage image(4, 3, 3, 0.5f);
  image.at(3, 0, 1) = std::numeric_limits<float>::quiet_NaN();
  image.at(3, 0, 2) = std::numeric_limits<float>::infinity();  // the same pixel: counted once
  image.at(1, 2, 0) = -std::numeric_limits<float>::infinity();
  NonFinitePixels found = nonFinitePixels(image);
  EXPECT_EQ(found.count, 2u);
  EXPECT_EQ(found.firstX, 3);
  EXPECT_EQ(found.firstY, 0);
  EXPECT_TRUE(std::isnan(found.firstValue));
}

TEST(NonFinitePixels, SingleChannelMaps) {
  FloatImage map(2, 2, 1, 0.0f);
  map.at(0, 1, 0) = std::numeric_limits<float>::infinity();
  NonFinitePixels found = nonFinitePixels(map);
  EXPECT_EQ(found.count, 1u);
  EXPECT_EQ(found.firstX, 0);
  EXPECT_EQ(found.firstY, 1);
}

TEST(RequireFiniteOutput, RefusesInOneLineNamingTheOutputAndTheFirstPixel) {
  FloatImage image(4, 3, 3, 0.5f);
  EXPECT_NO_THROW(requireFiniteOutput(image, "out.exr"));
  image.at(2, 1, 0) = std::numeric_limits<float>::infinity();
  try {
    requireFiniteOutput(image, "out.exr");
    FAIL() << "an image with an infinity was accepted";
  } catch (const Error& e) {
    EXPECT_EQ(std::string(e.what()),
              "out.exr: not written: 1 of 12 pixels came out non-finite (the first, (2, 1), holds inf); the "
              "scene's numbers overflow the float pipeline");
  }
}

}  // namespace
}  // namespace prism::imaging
