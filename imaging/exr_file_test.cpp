#include "imaging/exr_file.h"

#include <ImfChannelList.h>
#include <ImfFrameBuffer.h>
#include <ImfHeader.h>
#include <ImfInputFile.h>
#include <ImfMatrixAttribute.h>
#include <ImfOutputFile.h>
#include <ImfStandardAttributes.h>
#include <ImfStringAttribute.h>
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <fstream>
#include <limits>
#include <string>

#include "core/error.h"
#include "imaging/exr_band.h"
#include "spectral/observer.h"

namespace prism::imaging {
namespace {

// Each test writes in its own folder, per process so that builds testing side by side (release
// and asan) do not share it, and removed afterwards.
class Exr : public ::testing::Test {
 protected:
  void SetUp() override {
    mRoot = std::filesystem::path(::testing::TempDir()) / ("prism_exr_" + std::to_string(::getpid()));
    std::filesystem::remove_all(mRoot);
  }
  void TearDown() override {
    std::error_code ec;
    if (std::filesystem::exists(mRoot / "failed" / "locked", ec))
      std::filesystem::permissions(mRoot / "failed" / "locked", std::filesystem::perms::owner_all, ec);
    std::filesystem::remove_all(mRoot, ec);
  }
  std::filesystem::path freshDir(const std::string& name) const {
    std::filesystem::create_directories(mRoot / name);
    return mRoot / name;
  }
  // The Error reading `path` gives ("read" when it reads).
  static std::string readError(const std::filesystem::path& path) {
    try {
      readExr(path);
    } catch (const Error& e) {
      return e.what();
    }
    return "read";
  }

  std::filesystem::path mRoot;
};

std::vector<std::string> listing(const std::filesystem::path& dir) {
  std::vector<std::string> names;
  for (const auto& entry : std::filesystem::directory_iterator(dir)) names.push_back(entry.path().filename());
  std::sort(names.begin(), names.end());
  return names;
}

// Values over many octaves, both signs, distinct per pixel and channel.
FloatImage ramp(int width, int height, int channels) {
  FloatImage image(width, height, channels);
  for (std::size_t i = 0; i < image.pixels.size(); ++i) {
    double t = static_cast<double>(i) / static_cast<double>(image.pixels.size());
    image.pixels[i] =
        static_cast<float>((i % 7 == 3 ? -1.0 : 1.0) * std::exp2(-10.0 + 20.0 * t) * (1.0 + 0.37 * t));
  }
  return image;
}

TEST_F(Exr, FloatRoundTripIsExact) {
  std::filesystem::path p = freshDir("float") / "xyz.exr";
  FloatImage image = ramp(7, 5, 3);
  writeExr(p, image, {.colour = ColourMeaning::Xyz});
  ExrImage back = readExr(p);
  EXPECT_EQ(back.colour, ColourMeaning::Xyz);
  ASSERT_EQ(back.image.width, 7);
  ASSERT_EQ(back.image.height, 5);
  ASSERT_EQ(back.image.channels, 3);
  EXPECT_EQ(back.image.pixels, image.pixels);
  EXPECT_EQ(back.image.at(6, 4, 2), image.at(6, 4, 2));  // row 0 stays at the top
}

TEST_F(Exr, HalfRoundTripIsWithinHalfPrecision) {
  std::filesystem::path p = freshDir("half") / "rgba.exr";
  FloatImage image = ramp(9, 4, 4);
  writeExr(p, image, {.colour = ColourMeaning::LinearSrgb, .precision = ExrPrecision::Half});
  ExrImage back = readExr(p);
  EXPECT_EQ(back.colour, ColourMeaning::LinearSrgb);
  ASSERT_EQ(back.image.channels, 4);
  ASSERT_EQ(back.image.pixels.size(), image.pixels.size());
  for (std::size_t i = 0; i < image.pixels.size(); ++i) {
    // Round to nearest with an 11-bit significand: relative error at most 2⁻¹¹ (all values here
    // are normal halves, ≥ 2⁻¹⁰ > 2⁻¹⁴).
    float v = image.pixels[i];
    EXPECT_NEAR(back.image.pixels[i], v, std::abs(v) * std::exp2(-11.0f)) << "sample " << i;
  }
}

TEST_F(Exr, TheDisplayWhiteTravelsWithTheImage) {
  std::filesystem::path dir = freshDir("white");
  FloatImage image = ramp(3, 2, 3);
  writeExr(dir / "white.exr", image, {.colour = ColourMeaning::Xyz, .displayWhite = 3932.16});
  std::optional<double> white = readExr(dir / "white.exr").displayWhite;
  ASSERT_TRUE(white);
  EXPECT_NEAR(*white, 3932.16, 1e-3);
  writeExr(dir / "plain.exr", image);
  EXPECT_FALSE(readExr(dir / "plain.exr").displayWhite);
}

TEST_F(Exr, ACamerasRgbCarriesItsCameraAndMatrix) {
  std::filesystem::path dir = freshDir("camera");
  FloatImage image = ramp(3, 2, 3);
  Eigen::Matrix3d toXyz;
  toXyz << 0.61, 0.27, 0.08, 0.23, 0.94, -0.17, 0.01, -0.12, 1.3333333333333333;
  writeExr(dir / "cam.exr", image, {.colour = ColourMeaning::CameraRgb, .camera = ExrCamera{"nikon_d850", toXyz}});
  ExrImage back = readExr(dir / "cam.exr");
  ASSERT_TRUE(back.camera);
  EXPECT_EQ(back.camera->name, "nikon_d850");
  EXPECT_EQ(back.camera->toXyz, toXyz);  // doubles, exactly
  writeExr(dir / "plain.exr", image, {.colour = ColourMeaning::CameraRgb});
  EXPECT_FALSE(readExr(dir / "plain.exr").camera);
  // A matrix of another type (a part's string), or the name without its matrix, is refused.
  ExrBand band{.width = 1, .height = 1, .rowBegin = 0, .rows = 1,
               .attributes = {{"prism:colour", "camera-rgb"}, {kCameraAttribute, "nikon_d850"},
                              {kCameraToXyzAttribute, "1 0 0 0 1 0 0 0 1"}},
               .channels = {"R", "G", "B"}, .planes = {{0.5f}, {0.5f}, {0.5f}}};
  writeExrBand(dir / "string.exr", band);
  band.attributes.erase(kCameraToXyzAttribute);
  writeExrBand(dir / "half_said.exr", band);
  for (const auto& [file, message] :
       {std::pair{"string.exr", ": prism:cameraToXyz is of type string, not m33d"},
        std::pair{"half_said.exr", ": prism:camera without prism:cameraToXyz (a string and an m33d, written together)"}}) {
    EXPECT_EQ(readError(dir / file), (dir / file).string() + message);
  }
}

// A one-pixel file of three float channels with `header`'s attributes, as another program
// could write it.
void writeOnePixel(const std::filesystem::path& path, Imf::Header header, const std::array<const char*, 3>& names,
                   std::array<float, 3> pixel) {
  Imf::FrameBuffer frame;
  for (int c = 0; c < 3; ++c) {
    header.channels().insert(names[c], Imf::Channel(Imf::FLOAT));
    frame.insert(names[c], Imf::Slice(Imf::FLOAT, reinterpret_cast<char*>(&pixel[c]), sizeof(float), sizeof(float)));
  }
  Imf::OutputFile file(path.c_str(), header);
  file.setFrameBuffer(frame);
  file.writePixels(1);
}

// A one-pixel R, G, B file of the given colour meaning naming the camera nikon_d850 with `toXyz`:
// what writeExr never writes (it checks both).
void writeCameraAttributes(const std::filesystem::path& path, const char* colour, const Imath::M33d& toXyz) {
  Imf::Header header(1, 1);
  header.insert("prism:colour", Imf::StringAttribute(colour));
  header.insert(kCameraAttribute, Imf::StringAttribute("nikon_d850"));
  header.insert(kCameraToXyzAttribute, Imf::M33dAttribute(toXyz));
  writeOnePixel(path, header, {"R", "G", "B"}, {0.5f, 0.5f, 0.5f});
}

TEST_F(Exr, ACameraNamedOnOtherValuesOrWithoutAFiniteMatrixIsRefused) {
  std::filesystem::path dir = freshDir("camera_refused");
  const Imath::M33d identity;
  writeCameraAttributes(dir / "linear.exr", "linear-srgb", identity);
  writeCameraAttributes(dir / "camera.exr", "camera-rgb", identity);
  Imath::M33d infinite = identity;
  infinite[1][2] = std::numeric_limits<double>::infinity();
  writeCameraAttributes(dir / "infinite.exr", "camera-rgb", infinite);
  ASSERT_TRUE(readExr(dir / "camera.exr").camera);  // what the other two differ from is all they say
  for (const auto& [file, message] :
       {std::pair{"linear.exr", ": prism:camera on linear-srgb values, which are no camera's"},
        std::pair{"infinite.exr", ": prism:cameraToXyz: holds a value that is not finite"}}) {
    EXPECT_EQ(readError(dir / file), (dir / file).string() + message);
  }
}

TEST_F(Exr, ChannelNamesAndMeaningsRoundTrip) {
  std::filesystem::path dir = freshDir("meanings");
  FloatImage image = ramp(3, 2, 3);
  for (ColourMeaning colour :
       {ColourMeaning::LinearSrgb, ColourMeaning::Xyz, ColourMeaning::Xyz1964, ColourMeaning::CameraRgb}) {
    std::filesystem::path p = dir / (std::string(colourMeaningName(colour)) + ".exr");
    writeExr(p, image, {.colour = colour});
    EXPECT_EQ(readExr(p).colour, colour) << colourMeaningName(colour);
    // In R, G, B whatever they hold, as OpenEXR has CIE XYZ stored (with XYZ's chromaticities):
    // channels named X, Y, Z were read by other tools as a luminance Y, X and Z dropped.
    const Imf::InputFile file(p.c_str());
    EXPECT_NE(file.header().channels().findChannel("R"), nullptr) << colourMeaningName(colour);
    EXPECT_EQ(file.header().channels().findChannel("X"), nullptr) << colourMeaningName(colour);
    if (colour == ColourMeaning::Xyz || colour == ColourMeaning::Xyz1964) {
      ASSERT_TRUE(Imf::hasChromaticities(file.header()));
      EXPECT_EQ(Imf::chromaticities(file.header()).red, Imath::V2f(1.0f, 0.0f));
      EXPECT_EQ(Imf::chromaticities(file.header()).blue, Imath::V2f(0.0f, 0.0f));
    }
  }
  // Prism's older renders, channels X, Y, Z and no attribute, are still read as CIE XYZ.
  writeOnePixel(dir / "old_xyz.exr", Imf::Header(1, 1), {"X", "Y", "Z"}, {0.2f, 0.5f, 0.7f});
  const ExrImage old = readExr(dir / "old_xyz.exr");
  EXPECT_EQ(old.colour, ColourMeaning::Xyz);
  EXPECT_EQ(old.image.pixels, (std::vector<float>{0.2f, 0.5f, 0.7f}));
  // CIE 1964's tristimulus is stored like 1931's and told apart by its meaning; each observer's
  // images say which they hold (a 1964 render was written as "xyz").
  EXPECT_EQ(tristimulusMeaning(observer("cie1931")), ColourMeaning::Xyz);
  EXPECT_EQ(tristimulusMeaning(observer("cie1964")), ColourMeaning::Xyz1964);
  EXPECT_EQ(tristimulusMeaning(observer("nikon_d850")), ColourMeaning::CameraRgb);
  FloatImage map = ramp(4, 4, 1);
  writeExr(dir / "map.exr", map);
  ExrImage back = readExr(dir / "map.exr");
  EXPECT_EQ(back.image.channels, 1);
  EXPECT_EQ(back.image.pixels, map.pixels);
}

TEST_F(Exr, AtomicWriteLeavesOnlyTheFile) {
  std::filesystem::path dir = freshDir("atomic");
  writeExr(dir / "a.exr", ramp(2, 2, 3));
  writeExr(dir / "a.exr", ramp(3, 3, 3));  // replaces it
  EXPECT_EQ(listing(dir), std::vector<std::string>{"a.exr"});
  EXPECT_EQ(readExr(dir / "a.exr").image.width, 3);
}

TEST_F(Exr, FailedWritesLeaveNothingBehind) {
  std::filesystem::path dir = freshDir("failed");
  // The target is a folder: the temporary file is written, the rename fails, and it must go.
  std::filesystem::create_directories(dir / "taken.exr" / "inside");
  try {
    writeExr(dir / "taken.exr", ramp(2, 2, 3));
    FAIL() << "expected an Error";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("taken.exr"), std::string::npos) << e.what();
  }
  EXPECT_EQ(listing(dir), std::vector<std::string>{"taken.exr"});

  // Half overflow is refused before any file is made.
  FloatImage big(1, 1, 3, 1e6f);
  EXPECT_THROW(writeExr(dir / "big.exr", big, {.precision = ExrPrecision::Half}), Error);
  EXPECT_EQ(listing(dir), std::vector<std::string>{"taken.exr"});

  EXPECT_THROW(writeExr("/proc/prism_cannot_write.exr", ramp(1, 1, 3)), Error);

  // Permissions mean nothing to root, so only an unprivileged run can test a read-only folder.
  if (::geteuid() != 0) {
    std::filesystem::path locked = dir / "locked";
    std::filesystem::create_directories(locked);
    ::chmod(locked.c_str(), 0555);
    EXPECT_THROW(writeExr(locked / "x.exr", ramp(1, 1, 3)), Error);
    EXPECT_TRUE(listing(locked).empty());
    ::chmod(locked.c_str(), 0755);
  }
}

TEST_F(Exr, ReadErrorsNameTheFileOnOneLine) {
  std::filesystem::path dir = freshDir("errors");
  for (std::filesystem::path p : {dir / "missing.exr", dir / "text.exr"}) {
    if (p.filename() == "text.exr") std::ofstream(p) << "not an EXR\n";
    try {
      readExr(p);
      FAIL() << "expected an Error for " << p;
    } catch (const Error& e) {
      std::string message = e.what();
      EXPECT_EQ(message.rfind(p.string() + ": ", 0), 0u) << message;
      EXPECT_EQ(message.find('\n'), std::string::npos) << message;
    }
  }
}

}  // namespace
}  // namespace prism::imaging
