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
