#include "spectral/csv.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "spectral/error.h"
#include "spectral/error_test_support.h"

namespace prism {
namespace {

class CsvTest : public ::testing::Test {
 protected:
  std::filesystem::path write(const std::string& name, const std::string& text) {
    std::filesystem::path p = std::filesystem::path(::testing::TempDir()) / name;
    std::ofstream(p) << text;
    return p;
  }
};

TEST_F(CsvTest, ReadsQuotedFieldsAndSkipsBlankLines) {
  auto p = write("quoted.csv", "name,wavelength_nm,note\r\n\"a, b\",400,\"x\"\n\nc,410,y\n");
  CsvTable t = CsvTable::read(p);
  ASSERT_EQ(t.rows().size(), 2u);
  EXPECT_EQ(t.rows()[0].fields[0], "a, b");
  EXPECT_EQ(t.rows()[1].line, 4);
  EXPECT_EQ(t.number(t.rows()[1], 1), 410.0);
}

TEST_F(CsvTest, MalformedRowNamesFileAndLine) {
  auto p = write("short_row.csv", "wavelength_nm,value\n400,1\n410\n");
  EXPECT_EQ(errorOf([&] { CsvTable::read(p); }), p.string() + ":3: expected 2 fields, found 1");
}

TEST_F(CsvTest, BrokenQuotingIsReported) {
  auto p = write("bad_quote.csv", "wavelength_nm,value\n400,\"1\n");
  EXPECT_NE(errorOf([&] { CsvTable::read(p); }).find(p.string() + ":2: malformed CSV"), std::string::npos);
}

TEST_F(CsvTest, NonNumericFieldNamesLineAndColumn) {
  auto p = write("text.csv", "wavelength_nm,value\n400,1\n410,abc\n");
  EXPECT_EQ(errorOf([&] { readSpectrumCsv(p, Extrapolation::Zero); }),
            p.string() + ":3:2: expected a number in column 'value', found 'abc'");
}

TEST_F(CsvTest, NonFiniteValuesAreRejected) {
  for (const char* bad : {"nan", "inf", "-inf", "1e999"}) {
    auto p = write("nonfinite.csv", std::string("wavelength_nm,value\n400,1\n410,") + bad + "\n");
    EXPECT_NE(errorOf([&] { readSpectrumCsv(p, Extrapolation::Zero); }).find(":3:2:"),
              std::string::npos) << bad;
  }
}

TEST_F(CsvTest, WavelengthsMustIncrease) {
  auto p = write("order.csv", "wavelength_nm,value\n400,1\n410,1\n405,1\n");
  EXPECT_NE(errorOf([&] { readSpectrumCsv(p, Extrapolation::Zero); })
                .find(p.string() + ":4: wavelengths must increase strictly"),
            std::string::npos);
}

TEST_F(CsvTest, MissingFileIsNamed) {
  EXPECT_EQ(errorOf([] { CsvTable::read("/nonexistent/spd.csv"); }),
            "/nonexistent/spd.csv: cannot open file");
}

TEST_F(CsvTest, MissingExpectedColumnIsNamed) {
  auto p = write("columns.csv", "wavelength_nm,x_bar,y_bar\n400,1,1\n410,1,1\n");
  std::vector<std::string_view> expected{"x_bar", "y_bar", "z_bar"};
  EXPECT_EQ(errorOf([&] { SpectraTable::read(p, expected); }),
            p.string() + ":1: missing column 'z_bar'");
}

TEST_F(CsvTest, SpectrumFileNeedsTwoColumns) {
  auto p = write("three.csv", "wavelength_nm,a,b\n400,1,1\n410,1,1\n");
  EXPECT_NE(errorOf([&] { readSpectrumCsv(p, Extrapolation::Zero); }).find(":1: a spectrum file has two columns"),
            std::string::npos);
}

TEST_F(CsvTest, HeaderOnlyFileIsRejected) {
  auto p = write("empty.csv", "wavelength_nm,value\n");
  EXPECT_EQ(errorOf([&] { CsvTable::read(p); }), p.string() + ": no data rows after the header");
}

}  // namespace
}  // namespace prism
