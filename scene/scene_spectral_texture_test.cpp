// Materials with a spectral texture (docs/spectral-texture.md): read once per file, shaded only
// by PRT objects, and refused in one line when the file or its use is wrong; and conductors,
// which PRT objects (diffuse) refuse.
#include "scene/scene_loader.h"

#include <gtest/gtest.h>

#include <string>

#include "core/error_test_support.h"
#include "imaging/spectral_texture_file.h"
#include "scene/scene_folder_test_support.h"

namespace prism {
namespace {

using namespace testing_support;

class SpectralTextureScene : public SceneFolder {
 protected:
  void writeTexture(const std::string& name) {
    SpectralTexture t;
    t.width = 2;
    t.height = 1;
    t.wavelengthsNm = {400.0, 700.0};
    t.basis = Eigen::MatrixXd::Identity(2, 2);
    t.coefficients = {0.1f, 0.9f, 0.5f, 0.5f};
    imaging::writeSpectralTexture(mDir / name, t);
  }
  // Materials m and n alike; a sphere of m (with `technique`, e.g. `, "technique": "prt"`) and a
  // PRT sphere of n; a PRT section.
  fs::path sphere(const std::string& material, const std::string& technique) {
    return write("scene.json", R"({"camera": {"position": [0, 1, 5], "target": [0, 1, 0]},
  "materials": {"m": )" + material + R"(, "n": )" + material + R"(},
  "objects": [{"sphere": {"centre": [0, 0, 0], "radius": 1}, "material": "m")" + technique + R"(},
              {"sphere": {"centre": [3, 0, 0], "radius": 1}, "material": "n", "technique": "prt"}],
  "prt": {}})");
  }
};

TEST_F(SpectralTextureScene, PrtObjectsTakeItAndMaterialsShareTheFile) {
  writeTexture("paint.exr");
  Scene s = loadScene(sphere(R"({"spectral_texture": "paint.exr"})", R"(, "technique": "prt")"));
  ASSERT_EQ(s.materials.size(), 2u);
  ASSERT_TRUE(s.materials[0].spectralTexture);
  EXPECT_EQ(s.materials[0].spectralTexture, s.materials[1].spectralTexture);
  EXPECT_EQ(s.materials[0].spectralTexture->width, 2);
  EXPECT_EQ(s.materials[0].spectralTexture->texel(1, 0)[0], 0.5f);
}

TEST_F(SpectralTextureScene, OtherObjectsOtherReflectancesAndBadFilesAreRefused) {
  writeTexture("paint.exr");
  fs::path f = sphere(R"({"spectral_texture": "paint.exr"})", "");
  EXPECT_EQ(errorOf([&] { loadScene(f); }),
            f.string() + R"(: /objects/0: material 'm' has a spectral texture, which only PRT objects ("technique": "prt") shade)");
  f = sphere(R"({"spectral_texture": "paint.exr", "base_colour": [1, 0, 0]})", R"(, "technique": "prt")");
  EXPECT_EQ(errorOf([&] { loadScene(f); }),
            f.string() + ": /materials/m/spectral_texture: a spectral texture is the reflectance: give it or base_colour, not both");
  write("rgb.exr", "not an EXR");
  f = sphere(R"({"spectral_texture": "rgb.exr"})", R"(, "technique": "prt")");
  EXPECT_TRUE(startsWith(errorOf([&] { loadScene(f); }),
                         f.string() + ": /materials/m/spectral_texture: " + (mDir / "rgb.exr").string() + ": "));
}

TEST_F(SpectralTextureScene, AConductorOnAPrtObjectIsRefused) {
  fs::path f = sphere(R"({"conductor": "Au"})", "");
  EXPECT_EQ(errorOf([&] { loadScene(f); }),
            f.string() + ": /objects/1: material 'n' is a conductor, which PRT objects (diffuse by definition) cannot shade");
}

}  // namespace
}  // namespace prism
