#include "imaging/image_difference.h"

#include <gtest/gtest.h>

#include <Eigen/LU>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <string>
#include <vector>

#include "spectral/colour_difference.h"
#include "spectral/colour_space.h"
#include "core/error.h"

namespace prism::imaging {
namespace {

// IEC 61966-2-1 decode in double, written out here so the test does not share the code path.
double srgbDecode(double v) { return v <= 0.04045 ? v / 12.92 : std::pow((v + 0.055) / 1.055, 2.4); }

Eigen::Vector3d xyzOfSrgb8(int r, int g, int b) {
  Eigen::Vector3d linear(srgbDecode(r / 255.0), srgbDecode(g / 255.0), srgbDecode(b / 255.0));
  return colourSpace("srgb").rgbToXyz * linear;
}

TEST(ImageDifference, IdenticalImagesDifferByZero) {
  PngImage a(6, 4, {30, 140, 220});
  a.setPixel(2, 3, {255, 0, 7});
  ImageDifference d = compareImages(png8Input(a), png8Input(a), {.keepMap = true});
  EXPECT_EQ(d.stats.pixelCount, 24u);
  EXPECT_EQ(d.stats.meanDeltaE, 0.0);
  EXPECT_EQ(d.stats.maxDeltaE, 0.0);
  EXPECT_EQ(d.stats.fractionAbove, 0.0);
  EXPECT_EQ(d.stats.mae8, 0.0);
  EXPECT_EQ(d.stats.relativeError, 0.0);
  ASSERT_EQ(d.deltaEMap.channels, 1);
  EXPECT_EQ(d.deltaEMap.width, 6);

  FloatImage f(3, 3, 4, 0.25f);
  d = compareImages(linearInput(f, ColourMeaning::Xyz), linearInput(f, ColourMeaning::Xyz));
  EXPECT_EQ(d.stats.maxDeltaE, 0.0);
  EXPECT_TRUE(d.deltaEMap.pixels.empty());  // not asked for
}

// An image whose pixels do not fill its size is refused: it was read past its end.
TEST(ImageDifference, AnImageShortOfItsPixelsIsRefused) {
  FloatImage white(3, 3, 3, 1.0f), shortOfPixels(3, 3, 3, 1.0f);
  shortOfPixels.pixels.resize(3);
  EXPECT_THROW(compareImages(linearInput(shortOfPixels, ColourMeaning::Xyz, 1.0), linearInput(white, ColourMeaning::Xyz, 1.0)),
               Error);
}

TEST(ImageDifference, KnownPairMatchesCiede2000Directly) {
  // Uniform sRGB (128, 0, 0) against (130, 0, 0).
  const Eigen::Vector3d white = colourSpace("srgb").whiteXyz();
  const double expected = deltaE(xyzToLab(xyzOfSrgb8(128, 0, 0), white),
                                 xyzToLab(xyzOfSrgb8(130, 0, 0), white), DeltaEFormula::Ciede2000);
  ASSERT_GT(expected, 0.3);
  ImageDifference d =
      compareImages(png8Input(PngImage(4, 3, {128, 0, 0})), png8Input(PngImage(4, 3, {130, 0, 0})),
                    {.thresholdDeltaE = expected / 2});
  // The library decodes through the float transfer of shaders/shared/transfer.glsl.
  EXPECT_NEAR(d.stats.meanDeltaE, expected, 1e-4);
  EXPECT_NEAR(d.stats.medianDeltaE, expected, 1e-4);
  EXPECT_NEAR(d.stats.p99DeltaE, expected, 1e-4);
  EXPECT_NEAR(d.stats.maxDeltaE, expected, 1e-4);
  EXPECT_EQ(d.stats.fractionAbove, 1.0);
  EXPECT_DOUBLE_EQ(d.stats.mae8, 2.0 / 3.0);  // |128 − 130| in one channel of three
}

TEST(ImageDifference, LinearAndEightBitInputsAgree) {
  // The same colours as 8-bit sRGB, as linear sRGB, and as absolute XYZ with white Y = 100.
  PngImage a(2, 1, {200, 120, 40}), b(2, 1, {190, 125, 60});
  a.setPixel(1, 0, {12, 80, 160});
  FloatImage linearB(2, 1, 3), xyzB(2, 1, 3);
  for (int x = 0; x < 2; ++x) {
    Rgb8 v = b.pixel(x, 0);
    Eigen::Vector3d linear(srgbDecode(v.r / 255.0), srgbDecode(v.g / 255.0), srgbDecode(v.b / 255.0));
    Eigen::Vector3d xyz = 100.0 * (colourSpace("srgb").rgbToXyz * linear);
    for (int c = 0; c < 3; ++c) {
      linearB.at(x, 0, c) = static_cast<float>(linear[c]);
      xyzB.at(x, 0, c) = static_cast<float>(xyz[c]);
    }
  }
  DifferenceStats eight = compareImages(png8Input(a), png8Input(b)).stats;
  DifferenceStats linear =
      compareImages(png8Input(a), linearInput(linearB, ColourMeaning::LinearSrgb)).stats;
  DifferenceStats xyz = compareImages(png8Input(a), linearInput(xyzB, ColourMeaning::Xyz, 100.0)).stats;
  EXPECT_GT(eight.meanDeltaE, 1.0);
  // Float storage of the linear values: far below any visible difference.
  EXPECT_NEAR(linear.meanDeltaE, eight.meanDeltaE, 1e-3);
  EXPECT_NEAR(xyz.meanDeltaE, eight.meanDeltaE, 1e-3);
  EXPECT_NEAR(xyz.maxDeltaE, eight.maxDeltaE, 1e-3);
  // Re-encoding linear input to 8 bits gives back the same bytes.
  EXPECT_DOUBLE_EQ(linear.mae8, eight.mae8);
  EXPECT_NEAR(linear.relativeError, eight.relativeError, 1e-5);
}

// A Display P3 or Rec.2020 PNG is decoded as what it is: against an sRGB image of the same
// colours its ΔE00 is, pixel for pixel, that of its own bytes through its own transfer and
// primaries (8-bit rounding alone; measured mean 0.17 for P3, 0.21 for Rec.2020). Read as sRGB,
// it was 2.4 and 6.2.
TEST(ImageDifference, EightBitInputIsDecodedInItsOwnSpace) {
  const Eigen::Vector3d white = colourSpace("srgb").whiteXyz();
  PngImage reference(16, 16, {});
  for (int y = 0; y < 16; ++y)
    for (int x = 0; x < 16; ++x)
      reference.setPixel(x, y, {static_cast<std::uint8_t>(40 + 12 * x), static_cast<std::uint8_t>(60 + 10 * y), 128});
  for (const char* name : {"display-p3", "rec2020"}) {
    const RgbColourSpace& space = colourSpace(name);
    PngImage other(16, 16, {});
    other.setColourSpace(name);
    double expectedSum = 0.0, expectedMax = 0.0;
    for (int y = 0; y < 16; ++y)
      for (int x = 0; x < 16; ++x) {
        const Rgb8 v = reference.pixel(x, y);
        const Eigen::Vector3d xyz = xyzOfSrgb8(v.r, v.g, v.b);
        const Eigen::Vector3d encoded = space.encode(space.xyzToRgb * xyz) * 255.0;
        const Rgb8 bytes{static_cast<std::uint8_t>(std::lround(encoded.x())),
                         static_cast<std::uint8_t>(std::lround(encoded.y())),
                         static_cast<std::uint8_t>(std::lround(encoded.z()))};
        other.setPixel(x, y, bytes);
        const Eigen::Vector3d decoded = space.rgbToXyz * space.decode(Eigen::Vector3d(bytes.r, bytes.g, bytes.b) / 255.0);
        const double d = deltaE(xyzToLab(xyz, white), xyzToLab(decoded, white), DeltaEFormula::Ciede2000);
        expectedSum += d;
        expectedMax = std::max(expectedMax, d);
      }
    const DifferenceStats own = compareImages(png8Input(reference), png8Input(other)).stats;
    // The library decodes through the float transfer of shaders/shared/transfer.glsl.
    EXPECT_NEAR(own.meanDeltaE, expectedSum / 256.0, 1e-4) << name;
    EXPECT_NEAR(own.maxDeltaE, expectedMax, 1e-4) << name;
    PngImage untagged = other;
    untagged.setColourSpace("srgb");
    const DifferenceStats asSrgb = compareImages(png8Input(reference), png8Input(untagged)).stats;
    EXPECT_GE(asSrgb.meanDeltaE, 5.0 * own.meanDeltaE) << name;
    std::printf("%s: mean / max ΔE00 %.3f / %.3f decoded as itself, %.3f / %.3f as sRGB\n", name, own.meanDeltaE,
                own.maxDeltaE, asSrgb.meanDeltaE, asSrgb.maxDeltaE);
  }
}

TEST(ImageDifference, PercentilesOfAConstructedDistribution) {
  std::vector<float> values;
  for (int i = 99; i >= 0; --i) values.push_back(static_cast<float>(i));  // 0 … 99, unsorted
  DifferenceStats s = deltaEStats(values, 89.5);
  EXPECT_EQ(s.pixelCount, 100u);
  EXPECT_DOUBLE_EQ(s.meanDeltaE, 49.5);
  EXPECT_DOUBLE_EQ(s.medianDeltaE, 49.5);  // rank 49.5
  EXPECT_NEAR(s.p95DeltaE, 94.05, 1e-9);   // rank 94.05
  EXPECT_NEAR(s.p99DeltaE, 98.01, 1e-9);   // rank 98.01
  EXPECT_EQ(s.maxDeltaE, 99.0);
  EXPECT_DOUBLE_EQ(s.fractionAbove, 0.10);  // 90 … 99

  // Through images: 19 equal pixels and one that differs by d → P95 at rank 18.05 is 0.05 d.
  PngImage a(5, 4, {100, 100, 100}), b = a;
  b.setPixel(3, 2, {140, 100, 100});
  ImageDifference d = compareImages(png8Input(a), png8Input(b), {.keepMap = true});
  const double one = d.deltaEMap.at(3, 2, 0);
  EXPECT_GT(one, 5.0);
  EXPECT_EQ(d.stats.medianDeltaE, 0.0);
  EXPECT_NEAR(d.stats.p95DeltaE, 0.05 * one, 1e-6);
  EXPECT_NEAR(d.stats.meanDeltaE, one / 20, 1e-6);
  EXPECT_DOUBLE_EQ(d.stats.fractionAbove, 0.05);
}

TEST(ImageDifference, NonFinitePixelsCountAsInfinite) {
  std::vector<float> values = {1.0f, std::numeric_limits<float>::quiet_NaN(), 2.0f};
  DifferenceStats s = deltaEStats(values, 5.0);
  EXPECT_TRUE(std::isinf(s.maxDeltaE));
  EXPECT_DOUBLE_EQ(s.medianDeltaE, 2.0);
  EXPECT_NEAR(s.fractionAbove, 1.0 / 3.0, 1e-12);
}

TEST(ImageDifference, MeanAbsoluteErrorOnEightBits) {
  PngImage a(3, 2, {10, 20, 30}), b(3, 2, {13, 20, 24});
  EXPECT_DOUBLE_EQ(compareImages(png8Input(a), png8Input(b)).stats.mae8, 3.0);  // (3 + 0 + 6) / 3
}

TEST(ImageDifference, RelativeErrorOnLinearValues) {
  FloatImage a(2, 2, 3, 0.5f), b(2, 2, 3, 0.55f);
  auto relative = [](const FloatImage& x, const FloatImage& y) {
    return compareImages(linearInput(x, ColourMeaning::LinearSrgb), linearInput(y, ColourMeaning::LinearSrgb))
        .stats.relativeError;
  };
  EXPECT_NEAR(relative(a, b), 0.1, 1e-6);
  // Black reference: |a| is floored at ε = 0.01 of white.
  EXPECT_NEAR(relative(FloatImage(2, 2, 3, 0.0f), FloatImage(2, 2, 3, 0.001f)), 0.1, 1e-6);
}

TEST(ImageDifference, SizeMismatchNamesBothSizes) {
  try {
    compareImages(png8Input(PngImage(4, 3, {})), png8Input(PngImage(5, 3, {})));
    FAIL() << "expected an Error";
  } catch (const Error& e) {
    std::string message = e.what();
    EXPECT_NE(message.find("4 × 3"), std::string::npos) << message;
    EXPECT_NE(message.find("5 × 3"), std::string::npos) << message;
  }
}

TEST(ImageDifference, RefusesImagesWithoutColorimetry) {
  FloatImage f(2, 2, 3);
  EXPECT_THROW(compareImages(linearInput(f, ColourMeaning::CameraRgb), linearInput(f, ColourMeaning::Xyz)),
               Error);
  EXPECT_THROW(compareImages(linearInput(f, ColourMeaning::Xyz, 0.0), linearInput(f, ColourMeaning::Xyz)),
               Error);
  FloatImage map(2, 2, 1);
  EXPECT_THROW(compareImages(linearInput(map, ColourMeaning::Xyz), linearInput(f, ColourMeaning::Xyz)),
               Error);
}

// A camera's RGB is compared in XYZ through its matrix: the raw RGB of an XYZ image (the matrix's
// inverse applied) compares with it as equal, and through another matrix as different.
TEST(ImageDifference, ACamerasRgbComparesThroughItsMatrix) {
  Eigen::Matrix3d toXyz;
  toXyz << 0.61, 0.27, 0.08, 0.23, 0.94, -0.17, 0.01, -0.12, 1.2;
  FloatImage xyz(3, 2, 3), camera(3, 2, 3);
  for (std::size_t p = 0; p < xyz.pixelCount(); ++p) {
    const Eigen::Vector3d v(0.2 + 0.1 * static_cast<double>(p), 0.3, 0.25 + 0.05 * static_cast<double>(p));
    const Eigen::Vector3d raw = toXyz.inverse() * v;
    for (int c = 0; c < 3; ++c) {
      xyz.pixels[3 * p + static_cast<std::size_t>(c)] = static_cast<float>(v[c]);
      camera.pixels[3 * p + static_cast<std::size_t>(c)] = static_cast<float>(raw[c]);
    }
  }
  EXPECT_LT(compareImages(cameraInput(camera, toXyz), linearInput(xyz, ColourMeaning::Xyz)).stats.maxDeltaE, 1e-3);
  EXPECT_GT(compareImages(cameraInput(camera, Eigen::Matrix3d::Identity()), linearInput(xyz, ColourMeaning::Xyz))
                .stats.meanDeltaE,
            1.0);
}

TEST(ImageDifference, ResultDoesNotDependOnThreads) {
  FloatImage a(17, 23, 3), b(17, 23, 3);
  for (std::size_t i = 0; i < a.pixels.size(); ++i) {
    a.pixels[i] = static_cast<float>(i % 13) / 13.0f;
    b.pixels[i] = static_cast<float>((i * 7) % 11) / 11.0f;
  }
  auto run = [&](unsigned threads) {
    return compareImages(linearInput(a, ColourMeaning::LinearSrgb), linearInput(b, ColourMeaning::LinearSrgb),
                         {.threads = threads})
        .stats;
  };
  DifferenceStats one = run(1), many = run(4);
  EXPECT_EQ(one.meanDeltaE, many.meanDeltaE);
  EXPECT_EQ(one.p99DeltaE, many.p99DeltaE);
  EXPECT_EQ(one.mae8, many.mae8);
  EXPECT_EQ(one.relativeError, many.relativeError);
}

}  // namespace
}  // namespace prism::imaging
