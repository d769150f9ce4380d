#include "spectral/spectrum_csv.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "core/error.h"
#include "core/error_test_support.h"

namespace prism {
namespace {

class SpectrumCsvTest : public ::testing::Test {
 protected:
  std::filesystem::path write(const std::string& name, const std::string& text) {
    std::filesystem::path p = std::filesystem::path(::testing::TempDir()) / name;
    std::ofstream(p) << text;
    return p;
  }
};

TEST_F(SpectrumCsvTest, NonNumericFieldNamesLineAndColumn) {
  auto p = write("text.csv", "wavelength_nm,value\n400,1\n410,abc\n");
  EXPECT_EQ(errorOf([&] { readSpectrumCsv(p, Extrapolation::Zero); }),
            p.string() + ":3:2: expected a number in column 'value', found 'abc'");
}

TEST_F(SpectrumCsvTest, NonFiniteValuesAreRejected) {
  for (const char* bad : {"nan", "inf", "-inf", "1e999"}) {
    auto p = write("nonfinite.csv", std::string("wavelength_nm,value\n400,1\n410,") + bad + "\n");
    EXPECT_NE(errorOf([&] { readSpectrumCsv(p, Extrapolation::Zero); }).find(":3:2:"),
              std::string::npos) << bad;
  }
}

TEST_F(SpectrumCsvTest, WavelengthsMustIncrease) {
  auto p = write("order.csv", "wavelength_nm,value\n400,1\n410,1\n405,1\n");
  EXPECT_NE(errorOf([&] { readSpectrumCsv(p, Extrapolation::Zero); })
                .find(p.string() + ":4: wavelengths must increase strictly"),
            std::string::npos);
}

TEST_F(SpectrumCsvTest, MissingExpectedColumnIsNamed) {
  auto p = write("columns.csv", "wavelength_nm,x_bar,y_bar\n400,1,1\n410,1,1\n");
  std::vector<std::string_view> expected{"x_bar", "y_bar", "z_bar"};
  EXPECT_EQ(errorOf([&] { SpectraTable::read(p, expected); }),
            p.string() + ":1: missing column 'z_bar'");
}

TEST_F(SpectrumCsvTest, SpectrumFileNeedsTwoColumns) {
  auto p = write("three.csv", "wavelength_nm,a,b\n400,1,1\n410,1,1\n");
  EXPECT_NE(errorOf([&] { readSpectrumCsv(p, Extrapolation::Zero); }).find(":1: a spectrum file has two columns"),
            std::string::npos);
}

}  // namespace
}  // namespace prism
