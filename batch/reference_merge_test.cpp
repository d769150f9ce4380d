// The parts of a split reference render: written and read back, refused when they are not of one
// render or do not cover it exactly once, and merged into the whole render (bit for bit from
// rows, to float rounding from path indices) whatever their order, as often as asked.
#include "batch/reference_merge.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <string>

#include "core/error.h"
#include "core/worst_of.h"
#include "imaging/exr_band.h"
#include "imaging/exr_file.h"
#include "scene/scene_loader.h"
#include "spectral/rgb_to_spectrum_cache.h"
#include "spectral/spectral_texture.h"
#include "techniques/prt/prt_section.h"

namespace prism::batch {
namespace {

const std::filesystem::path kScene = std::filesystem::path(PRISM_SCENES_DIR) / "spheres_d65.json";

reference::ReferenceSettings settings() {
  reference::ReferenceSettings s;
  s.width = 24;
  s.height = 16;
  s.samplesPerPixel = 12;
  s.seed = 5;
  s.threads = 2;
  return s;
}

class ReferenceParts : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    sScene = new Scene(loadScene(kScene));
    sWhole = new reference::ReferenceImage(render({0, 16, 0, 12}));
  }
  static void TearDownTestSuite() {
    delete sWhole;
    delete sScene;
  }
  void SetUp() override {
    mRoot = std::filesystem::path(::testing::TempDir()) / ("prism_parts_" + std::to_string(::getpid()));
    std::filesystem::remove_all(mRoot);
  }
  void TearDown() override {
    std::error_code ec;
    std::filesystem::remove_all(mRoot, ec);
  }

  static reference::ReferenceImage render(const reference::ReferenceRegion& region) {
    return reference::renderReference(*sScene, rendererRgbToSpectrumTable("srgb"), settings(), region);
  }
  // Renders `region` into a part file named NAME.exr.
  std::filesystem::path part(const std::string& name, const reference::ReferenceRegion& region,
                             reference::ReferenceSettings s = settings()) {
    std::filesystem::path file = mRoot / (name + ".exr");
    writeReferencePart(file, partHeader(kScene, {}, *sScene, s, region, 9.0f), render(region));
    return file;
  }
  static std::string mergeError(const std::vector<std::filesystem::path>& files) {
    try {
      mergeReferenceParts(files);
    } catch (const Error& e) {
      return e.what();
    }
    return "merged";
  }

  static Scene* sScene;
  static reference::ReferenceImage* sWhole;
  std::filesystem::path mRoot;
};
Scene* ReferenceParts::sScene = nullptr;
reference::ReferenceImage* ReferenceParts::sWhole = nullptr;

TEST_F(ReferenceParts, APartRoundTripsItsHeaderAndPixels) {
  std::filesystem::path file = part("a", {4, 9, 3, 7});
  ReferencePart read = readReferencePart(file);
  EXPECT_EQ(read.header, partHeader(kScene, {}, *sScene, settings(), {4, 9, 3, 7}, 9.0f));
  EXPECT_EQ(read.header, readReferencePartHeader(file));
  reference::ReferenceImage expected = render({4, 9, 3, 7});
  EXPECT_EQ(read.image.tristimulus.pixels, expected.tristimulus.pixels);
  EXPECT_EQ(read.image.meanResidual.pixels, expected.meanResidual.pixels);
  EXPECT_EQ(read.image.variance.pixels, expected.variance.pixels);
  // The scene's identity is its bytes, its overrides and what it loaded from the files it names.
  EXPECT_NE(sceneHash(kScene, {}, *sScene), sceneHash(kScene, {"lights.0.spd=F11"}, *sScene));
  EXPECT_EQ(sceneHash(kScene, {"a=1"}, *sScene), sceneHash(kScene, {"a=1"}, *sScene));
  Scene edited = *sScene;  // as if a model changed between two tasks
  edited.meshes[0].vertices[0].position.x += 1e-3f;
  EXPECT_NE(sceneHash(kScene, {}, *sScene), sceneHash(kScene, {}, edited));
  edited = *sScene;  // or a spectrum
  edited.lights[0].spd *= 1.001;
  EXPECT_NE(sceneHash(kScene, {}, *sScene), sceneHash(kScene, {}, edited));
}

// What a scene loads besides meshes, textures and spectra: a spectral texture's values, and what
// a technique's section read from its own files (PRT's environment map). A task that finds its
// part complete skips it (the Slurm test), so an edited file must make another render.
TEST(SceneHash, CoversSpectralTexturesAndWhatSectionsLoad) {
  const std::filesystem::path textured = std::filesystem::path(PRISM_SCENES_DIR) / "prt_textures.json";
  const Scene scene = loadScene(textured);
  const std::string hash = sceneHash(textured, {}, scene);
  Scene edited = scene;
  auto it = std::find_if(edited.materials.begin(), edited.materials.end(),
                         [](const Material& m) { return m.spectralTexture != nullptr; });
  ASSERT_NE(it, edited.materials.end());
  auto texture = std::make_shared<SpectralTexture>(*it->spectralTexture);
  texture->coefficients[texture->coefficients.size() / 2] += 1e-3f;
  it->spectralTexture = texture;
  EXPECT_NE(hash, sceneHash(textured, {}, edited));

  const std::filesystem::path mapped = std::filesystem::path(PRISM_SCENES_DIR) / "prt_rock.json";
  const Scene rock = loadScene(mapped);
  const auto* prt = rock.techniques.find<prt::PrtSection>();
  ASSERT_TRUE(prt && prt->map);
  Scene remapped = rock;
  auto section = std::make_unique<prt::PrtSection>(*prt);
  auto map = std::make_shared<prt::PrtMap>(*prt->map);
  map->linearRgb[0] *= 1.01f;
  section->map = map;
  remapped.techniques.add(std::move(section));
  EXPECT_NE(sceneHash(mapped, {}, rock), sceneHash(mapped, {}, remapped));
  EXPECT_EQ(sceneHash(mapped, {}, rock), sceneHash(mapped, {}, Scene(rock)));
}

TEST_F(ReferenceParts, RowsMergeIntoTheWholeRenderBitForBit) {
  MergedReference merged = mergeReferenceParts({part("c", {11, 16, 0, 12}), part("a", {0, 5, 0, 12}),
                                                part("b", {5, 11, 0, 12})});
  EXPECT_EQ(merged.image.tristimulus.pixels, sWhole->tristimulus.pixels);
  EXPECT_EQ(merged.image.variance.pixels, sWhole->variance.pixels);
  EXPECT_EQ(merged.header.region, (reference::ReferenceRegion{0, 16, 0, 12}));
}

TEST_F(ReferenceParts, PathRangesMergeIntoTheWholeRenderToFloatRounding) {
  // Rows 0–7 by path indices 0:1, 1:5, 5:12; rows 8–15 whole: both kinds in one merge.
  std::vector<std::filesystem::path> files = {part("a", {0, 8, 0, 1}), part("b", {0, 8, 1, 5}),
                                              part("c", {0, 8, 5, 12}), part("d", {8, 16, 0, 12})};
  MergedReference merged = mergeReferenceParts(files);
  double worstMean = 0.0, worstVariance = 0.0;
  for (std::size_t k = 0; k < sWhole->tristimulus.pixels.size(); ++k) {
    const double whole = sWhole->tristimulus.pixels[k], mean = merged.image.tristimulus.pixels[k];
    if (whole != mean) worstMean = worstOf(worstMean, std::abs(mean - whole) / std::abs(whole));
    const double wv = sWhole->variance.pixels[k], v = merged.image.variance.pixels[k];
    if (wv != v) worstVariance = worstOf(worstVariance, std::abs(v - wv) / std::abs(wv));
  }
  EXPECT_LE(worstMean, 1.2e-7);  // one float rounding: the means agree to double precision first
  EXPECT_LE(worstVariance, 1e-5);  // Chan's sum against the whole render's Σx² − n·m²
  EXPECT_GT(sWhole->variance.pixels[3 * 100 + 1], 0.0f);  // a noisy image: the variances are tested
  // Rows 8–15 came from one part: bit for bit.
  const std::size_t half = sWhole->tristimulus.pixels.size() / 2;
  EXPECT_TRUE(std::equal(sWhole->variance.pixels.begin() + static_cast<std::ptrdiff_t>(half), sWhole->variance.pixels.end(),
                         merged.image.variance.pixels.begin() + static_cast<std::ptrdiff_t>(half)));
}

TEST_F(ReferenceParts, MergingDependsOnTheSetOfPartsAloneAndAgainGivesTheSame) {
  std::vector<std::filesystem::path> files = {part("a", {0, 16, 0, 3}), part("b", {0, 16, 3, 12})};
  MergedReference once = mergeReferenceParts(files);
  MergedReference again = mergeReferenceParts({files[1], files[0]});
  EXPECT_EQ(once.image.tristimulus.pixels, again.image.tristimulus.pixels);
  EXPECT_EQ(once.image.variance.pixels, again.image.variance.pixels);
  EXPECT_TRUE(std::filesystem::exists(files[0]) && std::filesystem::exists(files[1]));  // parts are only read
}

TEST_F(ReferenceParts, AGapIsRefusedNamingItsPathsAndRows) {
  std::vector<std::filesystem::path> files = {part("a", {0, 5, 0, 12}), part("b", {5, 11, 0, 4}),
                                              part("c", {5, 11, 8, 12}), part("d", {11, 16, 0, 12})};
  EXPECT_EQ(mergeError(files), "merge: samples 4:8 of rows 5–10 are missing");
  files = {part("a", {0, 5, 0, 12}), part("d", {11, 16, 0, 12})};
  EXPECT_EQ(mergeError(files), "merge: samples 0:12 of rows 5–10 are missing");
  files = {part("a", {0, 16, 0, 11})};
  EXPECT_EQ(mergeError(files), "merge: samples 11:12 of rows 0–15 are missing");
  EXPECT_EQ(mergeError({}), "merge: no parts given");
}

TEST_F(ReferenceParts, AnOverlapIsRefusedNamingBothParts) {
  std::filesystem::path a = part("a", {0, 8, 0, 12}), b = part("b", {6, 16, 0, 12});
  EXPECT_EQ(mergeError({a, b}), "merge: samples 0:12 of rows 6–7 are in both " + a.string() + " and " + b.string());
  std::filesystem::path c = part("c", {0, 16, 0, 6}), d = part("d", {0, 16, 4, 12});
  EXPECT_EQ(mergeError({d, c}), "merge: samples 4:6 of rows 0–15 are in both " + c.string() + " and " + d.string());
  EXPECT_EQ(mergeError({a, a}), "merge: samples 0:12 of rows 0–7 are in both " + a.string() + " and " + a.string());
}

TEST_F(ReferenceParts, PartsOfAnotherRenderAreRefused) {
  reference::ReferenceSettings otherSeed = settings();
  otherSeed.seed = 6;
  std::filesystem::path a = part("a", {0, 8, 0, 12}), b = part("b", {8, 16, 0, 12}, otherSeed);
  EXPECT_EQ(mergeError({a, b}), "merge: " + b.string() + " is a part of another render: its seed: \"6\"; " +
                                    a.string() + "'s: \"5\"");
  reference::ReferenceSettings global = settings();
  global.transport = reference::LightTransport::Global;
  std::filesystem::path c = part("c", {8, 16, 0, 12}, global);
  EXPECT_NE(mergeError({a, c}).find("its settings: \"transport=global"), std::string::npos) << mergeError({a, c});
  std::filesystem::path d = mRoot / "d.exr";
  writeReferencePart(d, partHeader(kScene, {"lights.0.spd=F11"}, *sScene, settings(), {8, 16, 0, 12}, 9.0f), render({8, 16, 0, 12}));
  EXPECT_NE(mergeError({a, d}).find("its scene: "), std::string::npos);
}

TEST_F(ReferenceParts, ACamerasPartsCarryItsMatrixIntoTheMerge) {
  reference::ReferenceSettings s = settings();
  s.observer = "nikon_d850";
  Eigen::Matrix3d m;
  m << 0.61, 0.27, 0.08, 0.23, 0.94, -0.17, 0.01, -0.12, 1.0 / 3.0;
  auto write = [&](const std::string& name, const reference::ReferenceRegion& region, const Eigen::Matrix3d& matrix) {
    ReferencePartHeader h = partHeader(kScene, {}, *sScene, s, region, 9.0f);
    h.cameraToXyz = matrix;
    const std::filesystem::path file = mRoot / (name + ".exr");
    writeReferencePart(file, h, reference::renderReference(*sScene, rendererRgbToSpectrumTable("srgb"), s, region));
    return file;
  };
  const std::filesystem::path top = write("top", {0, 8, 0, 12}, m), bottom = write("bottom", {8, 16, 0, 12}, m);
  EXPECT_EQ(readReferencePartHeader(top).cameraToXyz, m);  // every digit of every double
  EXPECT_EQ(mergeReferenceParts({top, bottom}).header.cameraToXyz, m);
  const std::filesystem::path other = write("other", {8, 16, 0, 12}, 2.0 * m);
  EXPECT_EQ(mergeError({top, other}),
            "merge: " + other.string() + ": its camera matrix is not " + top.string() + "'s (the parts of one render share it)");
  // A camera's part without its matrix says so (one written before parts recorded it).
  imaging::ExrBand band = imaging::readExrBand(top, true);
  band.attributes.erase("prism:cameraToXyz");
  imaging::writeExrBand(other, band);
  EXPECT_EQ(mergeError({other}), other.string() + ": not a part of a reference render (no prism:cameraToXyz)");
  band.attributes["prism:cameraToXyz"] = "1 0 0 0 1 0 0 0";
  imaging::writeExrBand(other, band);
  EXPECT_EQ(mergeError({other}), other.string() + ": not a part of a reference render (prism:cameraToXyz holds 8 numbers, not 9)");
}

TEST_F(ReferenceParts, AFileThatIsNotAWholePartIsRefused) {
  std::filesystem::path a = part("a", {0, 16, 0, 12});
  std::filesystem::resize_file(a, std::filesystem::file_size(a) - 100);
  EXPECT_NO_THROW(readReferencePartHeader(a));
  EXPECT_THROW(readReferencePart(a), Error);
  EXPECT_THROW(mergeReferenceParts({a}), Error);
  imaging::writeExr(mRoot / "image.exr", sWhole->tristimulus);
  EXPECT_EQ(mergeError({mRoot / "image.exr"}),
            (mRoot / "image.exr").string() + ": not a part of a reference render (no prism:part)");
  // Numbers no path tracer writes, named at their pixel: a negative estimate passed into the
  // merged image, a NaN was blamed on the scene's numbers.
  reference::ReferenceImage negative = render({0, 16, 0, 12});
  negative.tristimulus.pixels[3 * 5 + 2] = -1e6f;
  const std::filesystem::path n = mRoot / "negative.exr";
  writeReferencePart(n, partHeader(kScene, {}, *sScene, settings(), {0, 16, 0, 12}, 9.0f), negative);
  EXPECT_EQ(mergeError({n}), n.string() + ": channel Z, pixel (5, 0) of the part: -1000000 is not a finite, non-negative estimate");
  reference::ReferenceImage nan = render({0, 16, 0, 12});
  nan.variance.pixels[3 * 25 + 1] = std::numeric_limits<float>::quiet_NaN();
  writeReferencePart(n, partHeader(kScene, {}, *sScene, settings(), {0, 16, 0, 12}, 9.0f), nan);
  EXPECT_EQ(mergeError({n}), n.string() + ": channel variance.Y, pixel (1, 1) of the part: nan is not a finite, non-negative estimate");
  // A number no float holds is said as such, not as no number ("\"1e39\" is not a number").
  imaging::ExrBand band = imaging::readExrBand(n, true);
  band.attributes["prism:ev100"] = "1e39";
  const std::filesystem::path far = mRoot / "far.exr";
  imaging::writeExrBand(far, band);
  EXPECT_NE(mergeError({far}).find("prism:ev100 1e39 is out of its type's range"), std::string::npos) << mergeError({far});
}

}  // namespace
}  // namespace prism::batch
