#include "spectral/rgb_to_spectrum_part.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <fstream>
#include <iterator>
#include <limits>
#include <string>

#include "core/error.h"
#include "spectral/rgb_to_spectrum_optimiser.h"

namespace prism {
namespace {

class TableParts : public ::testing::Test {
 protected:
  void SetUp() override {
    mRoot = std::filesystem::path(::testing::TempDir()) / ("prism_table_parts_" + std::to_string(::getpid()));
    std::filesystem::remove_all(mRoot);
  }
  void TearDown() override {
    std::error_code ec;
    std::filesystem::remove_all(mRoot, ec);
  }
  // Task I of N's part of the sRGB 6³ table (108 columns).
  std::filesystem::path part(TaskIndex task, const std::string& gamut = "srgb") {
    const IndexRange columns = shareOf(task, tableColumns(6));
    TableBuildOptions options{gamut, 6, 1, {}};
    std::filesystem::path file = mRoot / ("part-" + std::to_string(task.index) + "-" + gamut + ".prismlut");
    saveTablePart(file, tablePart(buildRgbToSpectrumTable(options, columns), columns));
    return file;
  }
  std::string bytes(const std::filesystem::path& file) {
    std::ifstream in(file, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  }
  std::string mergeError(const std::vector<std::filesystem::path>& files) {
    try {
      mergeTableParts(files);
    } catch (const Error& e) {
      return e.what();
    }
    return "merged";
  }
  std::filesystem::path mRoot;
};

TEST_F(TableParts, PartsMergeIntoTheWholeTableByteForByte) {
  std::vector<std::filesystem::path> files = {part({2, 3}), part({0, 3}), part({1, 3})};
  EXPECT_TRUE(isTablePart(files[0]));
  mergeTableParts(files).save(mRoot / "merged.prismlut");
  buildRgbToSpectrumTable({"srgb", 6, 2, {}}).save(mRoot / "whole.prismlut");
  EXPECT_EQ(bytes(mRoot / "merged.prismlut"), bytes(mRoot / "whole.prismlut"));
  EXPECT_FALSE(isTablePart(mRoot / "whole.prismlut"));
}

TEST_F(TableParts, GapsOverlapsAndOtherTablesAreRefused) {
  std::filesystem::path a = part({0, 3}), c = part({2, 3});
  EXPECT_EQ(mergeError({a, c}), "merge: columns 36:72 are missing");
  EXPECT_EQ(mergeError({a, a}), "merge: columns 0:36 are in both " + a.string() + " and " + a.string());
  std::filesystem::path b = part({1, 3}), other = part({1, 3}, "rec2020");
  EXPECT_EQ(mergeError({a, other, c}), "merge: " + other.string() + " is a part of another table: rec2020 6³, " +
                                           a.string() + "'s is srgb 6³");
  std::filesystem::resize_file(b, std::filesystem::file_size(b) - 1);
  EXPECT_NE(mergeError({a, b, c}).find("truncated upsampling table part"), std::string::npos);
  // A part whose checksum holds but whose numbers are not: merged, the table failed to load.
  const IndexRange columns = shareOf({1, 3}, tableColumns(6));
  RgbToSpectrumPart broken = tablePart(buildRgbToSpectrumTable({"srgb", 6, 1, {}}, columns), columns);
  broken.coefficients[4] = std::numeric_limits<float>::quiet_NaN();
  saveTablePart(b, broken);
  EXPECT_EQ(mergeError({a, b, c}), b.string() + ": non-finite coefficient in upsampling table part");
}

}  // namespace
}  // namespace prism
