// Nebula scene files: the example loads; bad values are refused in one line naming the file and
// the JSON pointer; a density file is read beside the scene.
#include <gtest/gtest.h>

#include <string>

#include "core/data_files.h"
#include "core/error_test_support.h"
#include "core/temp_file_test_support.h"
#include "techniques/nebula/nebula_scene.h"

namespace prism::nebula {
namespace {

TEST(NebulaScene, TheExampleLoads) {
  NebulaScene s = loadNebulaScene(exampleSceneDirectory() / "nebula" / "nebula.json");
  EXPECT_EQ(s.model.density.nx, 64);
  EXPECT_EQ(s.model.stars.size(), 3u);
  EXPECT_EQ(s.model.filters, "hubble");
  EXPECT_EQ(s.steps, 100);
}

TEST(NebulaScene, BadValuesNameTheirPlace) {
  auto check = [](const std::string& name, const std::string& text, const std::string& expected) {
    auto path = writeTempFile(name, text);
    std::string e = errorOf([&] { loadNebulaScene(path); });
    EXPECT_EQ(e, path.string() + ": " + expected);
    EXPECT_EQ(e.find('\n'), std::string::npos);
  };
  const std::string noise = R"("density": {"noise": {"resolution": 4}})";
  check("n1.json", R"({"nebula": {)" + noise + R"(, "stars": [{"position": [0, 0, 0], "temperature": 50}]}})",
        "/nebula/stars/0/temperature: expected a number in [1000, 100000], got 50");
  check("n2.json", R"({"nebula": {)" + noise + R"(, "stars": [], "filters": "jwst"}})",
        "/nebula/filters: must be 'hubble' or 'cie1931', not 'jwst'");
  check("n3.json", R"({"nebula": {"density": {}, "stars": []}})",
        "/nebula/density: give exactly one of 'noise' and 'file'");
  check("n4.json", R"({"nebula": {)" + noise + R"(, "stars": [], "colour": 1}})",
        "/nebula/colour: unknown key (allowed: density, extinction, scattering, scattering_spectrum, emission, "
        "lines, ionisation, stars, star_model, filters, passbands, camera, steps)");
  check("n5.json", R"({"nebula": {)" + noise + R"(, "stars": [], "scattering_spectrum": [1, -2]}})",
        "/nebula/scattering_spectrum: the scattering spectrum is -0.56 at 780 nm: it must be ≥ 0 over 380–780 nm");
  check("n6z.json", R"({"nebula": {)" + noise + R"(, "stars": [], "scattering_spectrum": [0]}})",
        "/nebula/scattering_spectrum: the scattering spectrum peaks at 0 over 380–780 nm, below 1e-30: it has no shape; for "
        "no scattering give \"scattering\": 0");
  check("n6.json", R"({"nebula": {)" + noise + R"(, "stars": [], "scattering_spectrum": [1, 0, 0, 0, 1]}})",
        "/nebula/scattering_spectrum: expected 1 to 4 polynomial coefficients (up to a cubic), got 5");
  check("n7.json", R"({"nebula": {)" + noise + R"(, "stars": [], "scattering_spectrum": "blue"}})",
        "/nebula/scattering_spectrum: must be 'grey', 'ccm' or 1 to 4 polynomial coefficients, not 'blue'");
  check("n8.json", R"({"nebula": {)" + noise + R"(, "stars": [], "ionisation": {"front_radius": 0}}})",
        "/nebula/ionisation/front_radius: expected a number in (0, 4], got 0");
  check("n9.json", R"({"nebula": {)" + noise + R"(, "stars": [], "ionisation": {"front_width": 0.6}}})",
        "/nebula/ionisation/front_width: expected a number in (0, 0.5], got 0.6");
}

TEST(NebulaScene, IonisationZonesAreOptional) {
  const std::string noise = R"({"nebula": {"density": {"noise": {"resolution": 4}}, "stars": [])";
  EXPECT_FALSE(loadNebulaScene(writeTempFile("z1.json", noise + "}}")).model.ionisation.has_value());
  const NebulaModel m =
      loadNebulaScene(writeTempFile("z2.json", noise + R"(, "ionisation": {"front_radius": 0.45}}})")).model;
  EXPECT_EQ(m.ionisation, (IonisationModel{0.45, 0.1}));
}

TEST(NebulaScene, PassbandsAreMovedAndResizedPerChannel) {
  const std::string noise = R"({"nebula": {"density": {"noise": {"resolution": 4}}, "stars": [])";
  NebulaModel m = loadNebulaScene(writeTempFile(
      "p1.json", noise + R"(, "passbands": [{"shift_nm": 12.5}, {}, {"width": 2, "shift_nm": -5}]}})")).model;
  EXPECT_EQ(m.passbands[0], (PassbandEdit{12.5, 1.0}));
  EXPECT_EQ(m.passbands[1], PassbandEdit{});
  EXPECT_EQ(m.passbands[2], (PassbandEdit{-5.0, 2.0}));
  auto error = [&](const std::string& name, const std::string& passbands) {
    auto path = writeTempFile(name, noise + R"(, "passbands": )" + passbands + "}}");
    return errorOf([&] { loadNebulaScene(path); }).substr(path.string().size());
  };
  EXPECT_EQ(error("p2.json", "[{}, {}]"), ": /nebula/passbands: expected three passband edits, one per channel");
  EXPECT_EQ(error("p3.json", R"([{}, {"width": 8}, {}])"), ": /nebula/passbands/1/width: expected a number in [0.25, 4], got 8");
  EXPECT_EQ(error("p4.json", R"([{}, {"shift_nm": 200, "width": 0.25}, {}])"),
            ": /nebula/passbands: passband F656N: moved 200 nm and × 0.25 wide, nothing of it is left in 380–780 nm");
}

TEST(NebulaScene, TheScatteringSpectrum) {
  const std::string noise = R"({"nebula": {"density": {"noise": {"resolution": 4}}, "stars": [])";
  NebulaModel linear = loadNebulaScene(writeTempFile("s1.json", noise + R"(, "scattering_spectrum": [2, -1.5]}})")).model;
  EXPECT_DOUBLE_EQ(linear.scatteringSpectrum.at(0.5), 1.25);
  EXPECT_EQ(degree(linear.scatteringSpectrum), 1);
  NebulaModel ccm = loadNebulaScene(writeTempFile("s2.json", noise + R"(, "scattering_spectrum": "ccm"}})")).model;
  EXPECT_DOUBLE_EQ(ccm.scatteringSpectrum.at(0.55), ccmScattering().at(0.55));
  EXPECT_EQ(loadNebulaScene(writeTempFile("s3.json", noise + "}}")).model.scatteringSpectrum.at(0.7), 1.0);
}

TEST(NebulaScene, ADensityFileBesideTheScene) {
  DensityGrid g{2, 2, 2, std::vector<float>(8, 0.5f)};
  auto dir = std::filesystem::path(::testing::TempDir());
  writeDensityFile(dir / "cloud.density", g);
  auto path = writeTempFile("with_file.json", R"({"nebula": {"density": {"file": "cloud.density"}, "stars": []}})");
  EXPECT_EQ(loadNebulaScene(path).model.density.values, g.values);
  auto bad = writeTempFile("with_bad_file.json", R"({"nebula": {"density": {"file": "../x.density"}, "stars": []}})");
  std::string e = errorOf([&] { loadNebulaScene(bad); });
  EXPECT_EQ(e.rfind(bad.string() + ": /nebula/density/file: ", 0), 0u) << e;
}

}  // namespace
}  // namespace prism::nebula
