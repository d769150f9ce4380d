#include "imaging/exr_band.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <fstream>
#include <string>

#include "core/error.h"
#include "imaging/exr_file.h"

namespace prism::imaging {
namespace {

class ExrBandFile : public ::testing::Test {
 protected:
  void SetUp() override {
    mRoot = std::filesystem::path(::testing::TempDir()) / ("prism_exr_band_" + std::to_string(::getpid()));
    std::filesystem::remove_all(mRoot);
  }
  void TearDown() override {
    std::error_code ec;
    std::filesystem::remove_all(mRoot, ec);
  }
  std::filesystem::path mRoot;
};

ExrBand band() {
  ExrBand b;
  b.width = 5;
  b.height = 9;
  b.rowBegin = 3;
  b.rows = 2;
  b.attributes = {{"prism:part", "test"}, {"prism:samples", "0:16"}};
  b.channels = {"X", "Y", "Z", "variance.Y"};
  for (int c = 0; c < 4; ++c) {
    std::vector<float> plane;
    for (int i = 0; i < 10; ++i) plane.push_back(static_cast<float>(c * 100 + i) + 0.25f);
    b.planes.push_back(plane);
  }
  return b;
}

TEST_F(ExrBandFile, RoundTripsRowsChannelsAndAttributes) {
  ExrBand written = band();
  writeExrBand(mRoot / "band.exr", written);
  ExrBand header = readExrBand(mRoot / "band.exr", false);
  EXPECT_EQ(header.width, 5);
  EXPECT_EQ(header.height, 9);
  EXPECT_EQ(header.rowBegin, 3);
  EXPECT_EQ(header.rows, 2);
  EXPECT_EQ(header.attributes.at("prism:samples"), "0:16");
  EXPECT_TRUE(header.planes.empty());
  ExrBand read = readExrBand(mRoot / "band.exr", true);
  ASSERT_EQ(read.channels.size(), 4u);  // OpenEXR lists them by name
  for (std::size_t c = 0; c < read.channels.size(); ++c) {
    auto k = std::find(written.channels.begin(), written.channels.end(), read.channels[c]) - written.channels.begin();
    EXPECT_EQ(read.planes[c], written.planes[static_cast<std::size_t>(k)]) << read.channels[c];
  }
  // An EXR reader sees the band's colour in its rows.
  ExrImage image = readExr(mRoot / "band.exr");
  EXPECT_EQ(image.image.height, 2);
  EXPECT_EQ(image.image.at(1, 0, 1), 101.25f);
}

TEST_F(ExrBandFile, ATruncatedBandIsAnErrorNamingTheFile) {
  writeExrBand(mRoot / "band.exr", band());
  const auto size = std::filesystem::file_size(mRoot / "band.exr");
  std::filesystem::resize_file(mRoot / "band.exr", size - 20);
  EXPECT_NO_THROW(readExrBand(mRoot / "band.exr", false));  // the header is whole
  try {
    readExrBand(mRoot / "band.exr", true);
    FAIL() << "a truncated band was read";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("band.exr: cannot read EXR"), std::string::npos) << e.what();
  }
  std::ofstream(mRoot / "text.exr") << "not an image";
  EXPECT_THROW(readExrBand(mRoot / "text.exr", false), Error);
}

}  // namespace
}  // namespace prism::imaging
