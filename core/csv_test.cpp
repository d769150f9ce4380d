#include "core/csv.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "core/error.h"
#include "core/error_test_support.h"

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

TEST_F(CsvTest, MissingFileIsNamed) {
  EXPECT_EQ(errorOf([] { CsvTable::read("/nonexistent/spd.csv"); }),
            "/nonexistent/spd.csv: cannot open file");
}

TEST_F(CsvTest, HeaderOnlyFileIsRejected) {
  auto p = write("empty.csv", "wavelength_nm,value\n");
  EXPECT_EQ(errorOf([&] { CsvTable::read(p); }), p.string() + ": no data rows after the header");
}

}  // namespace
}  // namespace prism
