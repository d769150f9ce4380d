#include "spectral/spectrum_csv.h"

#include <gtest/gtest.h>

#include "core/error.h"
#include "core/error_test_support.h"
#include "core/temp_file_test_support.h"

namespace prism {
namespace {

TEST(SpectrumCsvTest, NonNumericFieldNamesLineAndColumn) {
  auto p = writeTempFile("text.csv", "wavelength_nm,value\n400,1\n410,abc\n");
  EXPECT_EQ(errorOf([&] { readSpectrumCsv(p, Extrapolation::Zero); }),
            p.string() + ":3:2: expected a number in column 'value', found 'abc'");
}

TEST(SpectrumCsvTest, NonFiniteValuesAreRejected) {
  for (const char* bad : {"nan", "inf", "-inf", "1e999"}) {
    auto p = writeTempFile("nonfinite.csv", std::string("wavelength_nm,value\n400,1\n410,") + bad + "\n");
    EXPECT_NE(errorOf([&] { readSpectrumCsv(p, Extrapolation::Zero); }).find(":3:2:"),
              std::string::npos) << bad;
  }
}

TEST(SpectrumCsvTest, WavelengthsMustIncrease) {
  auto p = writeTempFile("order.csv", "wavelength_nm,value\n400,1\n410,1\n405,1\n");
  EXPECT_NE(errorOf([&] { readSpectrumCsv(p, Extrapolation::Zero); })
                .find(p.string() + ":4: wavelengths must increase strictly"),
            std::string::npos);
}

TEST(SpectrumCsvTest, WavelengthsMustBePositive) {
  auto p = writeTempFile("negative.csv", "wavelength_nm,value\n-5,1\n410,1\n");
  EXPECT_EQ(errorOf([&] { readSpectrumCsv(p, Extrapolation::Zero); }),
            p.string() + ":2: wavelengths must be positive (-5 nm)");
}

// A wavelength beyond ±1e12 (the limit of every number Prism reads), and a spectrum wholly
// outside 360–830 nm, which read as its end values extrapolated (a flat grey).
TEST(SpectrumCsvTest, WavelengthsMustBeWithinReachAndMeetTheRenderedRange) {
  auto huge = writeTempFile("huge.csv", "wavelength_nm,value\n400,0.5\n1e30,0.5\n");
  EXPECT_EQ(errorOf([&] { readSpectrumCsv(huge, Extrapolation::Zero); }),
            huge.string() + ":3:1: value '1e30' is beyond ±1e12, the most any number Prism reads may reach");
  auto outside = writeTempFile("outside.csv", "wavelength_nm,value\n100,0.5\n200,0.5\n");
  EXPECT_EQ(errorOf([&] { readSpectrumCsv(outside, Extrapolation::Zero); }),
            outside.string() + ": its wavelengths (100–200 nm) lie outside 360–830 nm, the range Prism renders");
  auto overlapping = writeTempFile("overlapping.csv", "wavelength_nm,value\n200,0.5\n360,0.5\n");
  EXPECT_NO_THROW(readSpectrumCsv(overlapping, Extrapolation::Zero));
}

TEST(SpectrumCsvTest, MissingExpectedColumnIsNamed) {
  auto p = writeTempFile("columns.csv", "wavelength_nm,x_bar,y_bar\n400,1,1\n410,1,1\n");
  std::vector<std::string_view> expected{"x_bar", "y_bar", "z_bar"};
  EXPECT_EQ(errorOf([&] { SpectraTable::read(p, expected); }),
            p.string() + ":1: missing column 'z_bar'");
}

TEST(SpectrumCsvTest, SpectrumFileNeedsTwoColumns) {
  auto p = writeTempFile("three.csv", "wavelength_nm,a,b\n400,1,1\n410,1,1\n");
  EXPECT_NE(errorOf([&] { readSpectrumCsv(p, Extrapolation::Zero); }).find(":1: a spectrum file has two columns"),
            std::string::npos);
}

// A data file's notes: '#' lines are skipped, and the header's errors name its own line. A
// comment before the header was read as a one-column header, and the real header blamed.
TEST(SpectrumCsvTest, CommentLinesAreSkippedAndTheHeaderNamedByItsLine) {
  auto noted = writeTempFile("noted.csv", "# measured 2026\n  # by hand\nwavelength_nm,value\n400,1\n# a gap\n500,2\n");
  TabulatedSpectrum s = readSpectrumCsv(noted, Extrapolation::Zero);
  EXPECT_DOUBLE_EQ(s.at(450.0), 1.5);
  EXPECT_EQ(s.lambdasNm().size(), 2u);
  auto commentedHeader = writeTempFile("commented_header.csv", "# wavelength_nm,value\n400,1\n500,2\n");
  EXPECT_EQ(errorOf([&] { readSpectrumCsv(commentedHeader, Extrapolation::Zero); }),
            commentedHeader.string() + ":2: expected a header line (e.g. wavelength_nm,value) before the numbers, got 400");
  auto three = writeTempFile("noted_three.csv", "# notes\nwavelength_nm,a,b\n400,1,1\n410,1,1\n");
  EXPECT_EQ(errorOf([&] { readSpectrumCsv(three, Extrapolation::Zero); }),
            three.string() + ":2: a spectrum file has two columns (wavelength in nm, value), found 3");
}

}  // namespace
}  // namespace prism
