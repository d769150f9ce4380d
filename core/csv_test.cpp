#include "core/csv.h"

#include <gtest/gtest.h>

#include "core/error.h"
#include "core/error_test_support.h"
#include "core/temp_file_test_support.h"

namespace prism {
namespace {

TEST(CsvTest, ReadsQuotedFieldsAndSkipsBlankLines) {
  auto p = writeTempFile("quoted.csv", "name,wavelength_nm,note\r\n\"a, b\",400,\"x\"\n\nc,410,y\n");
  CsvTable t = CsvTable::read(p);
  ASSERT_EQ(t.rows().size(), 2u);
  EXPECT_EQ(t.rows()[0].fields[0], "a, b");
  EXPECT_EQ(t.rows()[1].line, 4);
  EXPECT_EQ(t.number(t.rows()[1], 1), 410.0);
}

// '#' lines are notes wherever they are, and the header is the first other line.
TEST(CsvTest, CommentLinesAreSkippedAndTheHeaderKeepsItsLine) {
  auto p = writeTempFile("noted.csv", "# source: a lab\n\n  # measured 2026\nwavelength_nm,value\n400,1\n# gap\n410,2\n");
  CsvTable t = CsvTable::read(p);
  EXPECT_EQ(t.headerLine(), 4);
  ASSERT_EQ(t.rows().size(), 2u);
  EXPECT_EQ(t.rows()[1].line, 7);
  EXPECT_EQ(errorOf([&] { t.column("z"); }), p.string() + ":4: missing column 'z'");
  auto notes = writeTempFile("only_notes.csv", "# nothing here\n\n");
  EXPECT_EQ(errorOf([&] { CsvTable::read(notes); }),
            notes.string() + ": no header line (the file is empty, or blank and # lines)");
}

TEST(CsvTest, MalformedRowNamesFileAndLine) {
  auto p = writeTempFile("short_row.csv", "wavelength_nm,value\n400,1\n410\n");
  EXPECT_EQ(errorOf([&] { CsvTable::read(p); }), p.string() + ":3: expected 2 fields, found 1");
}

TEST(CsvTest, BrokenQuotingIsReported) {
  auto p = writeTempFile("bad_quote.csv", "wavelength_nm,value\n400,\"1\n");
  EXPECT_NE(errorOf([&] { CsvTable::read(p); }).find(p.string() + ":2: malformed CSV"), std::string::npos);
}

TEST(CsvTest, MissingFileIsNamed) {
  EXPECT_EQ(errorOf([] { CsvTable::read("/nonexistent/spd.csv"); }),
            "/nonexistent/spd.csv: cannot open: no such file");
}

TEST(CsvTest, HeaderOnlyFileIsRejected) {
  auto p = writeTempFile("empty.csv", "wavelength_nm,value\n");
  EXPECT_EQ(errorOf([&] { CsvTable::read(p); }), p.string() + ": no data rows after the header");
}

}  // namespace
}  // namespace prism
