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
            p.string() + ":2: wavelengths must be positive (-5.000000 nm)");
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

}  // namespace
}  // namespace prism
