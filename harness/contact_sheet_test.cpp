// The contact sheet (contact_sheet.h): shrinking averages light, not codes; cells keep their
// images' aspect, centred, labelled; what is not sRGB is refused.
#include "harness/contact_sheet.h"

#include <gtest/gtest.h>

#include <vector>

#include "core/error.h"

namespace prism::harness {
namespace {

TEST(ContactSheet, ShrinkingAveragesLinearLightNotCodes) {
  imaging::PngImage checker(2, 2, {0, 0, 0});
  checker.setPixel(0, 0, {255, 255, 255});
  checker.setPixel(1, 1, {255, 255, 255});
  // Half the light is sRGB 188 (0.5 encodes to 0.7354); the codes' mean would be 128.
  EXPECT_EQ(shrinkSrgb(checker, 1, 1).pixel(0, 0), (imaging::Rgb8{188, 188, 188}));
  const imaging::PngImage flat(6, 4, {100, 30, 200});
  const imaging::PngImage small = shrinkSrgb(flat, 4, 3);  // uneven footprints
  for (int y = 0; y < 3; ++y)
    for (int x = 0; x < 4; ++x) EXPECT_EQ(small.pixel(x, y), (imaging::Rgb8{100, 30, 200})) << x << "," << y;
}

TEST(ContactSheet, CellsKeepTheirImagesAspectCentredAndLabelled) {
  const imaging::PngImage wide(128, 72, {0, 200, 0}), square(72, 72, {200, 0, 0});
  const std::vector<SheetCell> cells{{&wide, "wide"}, {&square, "square"}, {&wide, "third"}};
  const imaging::PngImage sheet = contactSheet(cells, {.columns = 2, .cellWidth = 64, .cellHeight = 36});
  ASSERT_EQ(sheet.width(), 128);
  ASSERT_EQ(sheet.height(), 72);  // two rows: the third cell starts the second
  // Below the label's strip (18 rows):
  EXPECT_EQ(sheet.pixel(32, 30), (imaging::Rgb8{0, 200, 0}));       // the wide image fills its cell
  EXPECT_EQ(sheet.pixel(64 + 32, 30), (imaging::Rgb8{200, 0, 0}));  // the square, 36 × 36 in the middle
  EXPECT_EQ(sheet.pixel(64 + 13, 30), (imaging::Rgb8{0, 0, 0}));    // beside it, black
  EXPECT_EQ(sheet.pixel(64 + 14, 30), (imaging::Rgb8{200, 0, 0}));
  EXPECT_EQ(sheet.pixel(64 + 49, 30), (imaging::Rgb8{200, 0, 0}));
  EXPECT_EQ(sheet.pixel(64 + 50, 30), (imaging::Rgb8{0, 0, 0}));
  EXPECT_EQ(sheet.pixel(64 + 32, 36 + 30), (imaging::Rgb8{0, 0, 0}));  // no fourth cell
  int white = 0;  // the label's strokes, in the top left of the first cell
  for (int y = 0; y < 18; ++y)
    for (int x = 0; x < 64; ++x) white += sheet.pixel(x, y) == imaging::Rgb8{255, 255, 255};
  EXPECT_GT(white, 10);
}

TEST(ContactSheet, RefusesWhatItCannotShow) {
  imaging::PngImage p3(8, 8, {10, 10, 10});
  p3.setColourSpace("display-p3");
  const std::vector<SheetCell> cells{{&p3, "p3"}};
  EXPECT_THROW(contactSheet(cells, {}), Error);
  const imaging::PngImage srgb(8, 8, {10, 10, 10});
  const std::vector<SheetCell> fine{{&srgb, "srgb"}};
  EXPECT_THROW(contactSheet(fine, {.columns = 0}), Error);
  EXPECT_THROW(contactSheet(fine, {.cellWidth = 8}), Error);
  EXPECT_NO_THROW(contactSheet(fine, {}));
}

}  // namespace
}  // namespace prism::harness
