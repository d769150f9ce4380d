#include "imaging/heatmap.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace prism::imaging {
namespace {

constexpr Rgb8 kBottom{0x00, 0x00, 0x04}, kMiddle{0xBC, 0x37, 0x54}, kTop{0xFC, 0xFF, 0xA4};

TEST(HeatMap, ScaleEndsAndMiddle) {
  EXPECT_EQ(heatColour(0.0, 10.0), kBottom);
  EXPECT_EQ(heatColour(-3.0, 10.0), kBottom);
  EXPECT_EQ(heatColour(5.0, 10.0), kMiddle);
  EXPECT_EQ(heatColour(10.0, 10.0), kTop);
  EXPECT_EQ(heatColour(1e9, 10.0), kTop);
  EXPECT_EQ(heatColour(2.0, 2.0), kTop);  // the top follows the parameter
  EXPECT_EQ(heatColour(std::numeric_limits<double>::quiet_NaN(), 10.0), kHeatNaN);
}

TEST(HeatMap, ScaleGetsLighterAllTheWay) {
  double last = -1.0;
  for (int i = 0; i <= 100; ++i) {
    Rgb8 c = heatColour(i / 10.0, 10.0);
    double luma = 0.2126 * c.r + 0.7152 * c.g + 0.0722 * c.b;  // rough, on encoded values
    EXPECT_GE(luma, last) << "ΔE " << i / 10.0;
    last = luma;
  }
}

TEST(HeatMap, PixelsAndLegend) {
  FloatImage map(120, 2, 1);
  map.at(119, 1, 0) = 10.0f;
  map.at(60, 0, 0) = std::numeric_limits<float>::quiet_NaN();
  PngImage heat = heatMap(map);
  ASSERT_EQ(heat.width(), 120);
  ASSERT_EQ(heat.height(), 2 + kHeatLegendHeight);
  EXPECT_EQ(heat.pixel(0, 0), kBottom);
  EXPECT_EQ(heat.pixel(119, 1), kTop);
  EXPECT_EQ(heat.pixel(60, 0), kHeatNaN);
  // The legend's bar runs from the bottom colour at the left to the top colour at the right.
  EXPECT_EQ(heat.pixel(0, 2 + 5), kBottom);
  EXPECT_EQ(heat.pixel(119, 2 + 5), kTop);

  PngImage bare = heatMap(map, {.maxDeltaE = 20.0, .legend = false});
  EXPECT_EQ(bare.height(), 2);
  EXPECT_EQ(bare.pixel(119, 1), kMiddle);
}

TEST(Histogram, DrawsBarsInTheScaleColours) {
  FloatImage map(10, 10, 1);
  for (int i = 0; i < 100; ++i) map.pixels[static_cast<std::size_t>(i)] = i < 90 ? 0.1f : 50.0f;
  PngImage histogram = deltaEHistogram(map, {.maxDeltaE = 10.0, .bins = 10, .width = 300, .height = 150});
  ASSERT_EQ(histogram.width(), 300);
  ASSERT_EQ(histogram.height(), 150);
  int firstBin = 0, overflow = 0;
  for (int y = 0; y < histogram.height(); ++y)
    for (int x = 0; x < histogram.width(); ++x) {
      firstBin += histogram.pixel(x, y) == heatColour(0.5, 10.0);
      overflow += histogram.pixel(x, y) == kTop;
    }
  EXPECT_GT(firstBin, 100);  // the tall bar of 90 pixels
  EXPECT_GT(overflow, 10);   // the ≥ max bar of 10
  EXPECT_GT(firstBin, 5 * overflow);
  histogram.write(std::filesystem::path(::testing::TempDir()) / "prism_heatmap" / "histogram.png");
}

}  // namespace
}  // namespace prism::imaging
