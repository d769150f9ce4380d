#include "scene/gltf_loader.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>
#include <string>

#include <nlohmann/json.hpp>

#include <glm/gtc/matrix_transform.hpp>

#include "core/error.h"
#include "core/error_test_support.h"
#include "imaging/png_file.h"

namespace prism {
namespace {

namespace fs = std::filesystem;
const fs::path kGltfFixtures = PRISM_SCENE_TEST_DIR;

// Float positions through a few matrix products: a few ulps of the coordinates (≈ 10).
constexpr float kTolerance = 1e-5f;

void expectNear(const glm::vec3& a, const glm::vec3& b, float tolerance = kTolerance) {
  EXPECT_NEAR(a.x, b.x, tolerance);
  EXPECT_NEAR(a.y, b.y, tolerance);
  EXPECT_NEAR(a.z, b.z, tolerance);
}

// quad.gltf: node "parent" translates by (1, 2, 3); its child rotates 90° about +y and scales
// by 2; the mesh is a unit quad in the xy plane facing +z (uv (0, 0) at its top-left).
TEST(GltfLoader, NodeTransformsApplyToPositionsNormalsAndTangents) {
  Scene scene;
  appendGltf(kGltfFixtures / "quad.gltf", kGltfFixtures, {}, scene);
  ASSERT_EQ(scene.meshes.size(), 2u);
  const Mesh& quad = scene.meshes[0];
  ASSERT_EQ(quad.vertices.size(), 4u);
  EXPECT_EQ(quad.indices, (std::vector<std::uint32_t>{0, 1, 2, 0, 2, 3}));
  // (0.5, −0.5, 0) ·2 → (1, −1, 0), R_y(90°) → (0, −1, −1), + (1, 2, 3) → (1, 1, 2).
  expectNear(quad.vertices[1].position, {1.0f, 1.0f, 2.0f});
  expectNear(quad.vertices[3].position, {1.0f, 3.0f, 4.0f});
  for (const Vertex& v : quad.vertices) {
    expectNear(v.normal, {1.0f, 0.0f, 0.0f});  // +z turned by R_y(90°)
    // Computed tangents: along +u, which runs along +x in the model, −z in the world; the
    // bitangent cross(n, t)·w along −v (image up), +y in the model and the world.
    expectNear(glm::vec3(v.tangent), {0.0f, 0.0f, -1.0f});
    EXPECT_EQ(v.tangent.w, 1.0f);
  }
  EXPECT_EQ(quad.vertices[3].uv, glm::vec2(0.0f, 0.0f));
}

// quad.gltf edited, written with its checker.png into a fresh folder `name` under the test's
// temporary one: the edited file.
fs::path editedQuad(const std::string& name, const std::function<void(nlohmann::json&)>& edit) {
  const fs::path dir = fs::path(::testing::TempDir()) / name;
  fs::remove_all(dir);
  fs::create_directories(dir);
  fs::copy_file(kGltfFixtures / "checker.png", dir / "checker.png");
  nlohmann::json gltf = nlohmann::json::parse(std::ifstream(kGltfFixtures / "quad.gltf"));
  edit(gltf);
  std::ofstream(dir / "quad.gltf") << gltf.dump();
  return dir / "quad.gltf";
}

TEST(GltfLoader, NodeNumbersStayWithinTheScenesRangeAndAZeroScaleHidesItsNode) {
  const fs::path far = editedQuad("far_quad", [](nlohmann::json& g) { g["nodes"][0]["translation"] = {1e30, 0, 0}; });
  try {
    Scene scene;
    appendGltf(far, far.parent_path(), {}, scene);
    ADD_FAILURE() << "a node 1e30 m away was accepted";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("/nodes/0/translation/0: expected a number within ±1e12, got 1e+30"),
              std::string::npos) << e.what();
  }
  const fs::path hidden = editedQuad("hidden_quad", [](nlohmann::json& g) { g["nodes"][0]["scale"] = {0, 0, 0}; });
  Scene scene;
  appendGltf(hidden, hidden.parent_path(), {}, scene);
  EXPECT_TRUE(scene.meshes.empty());  // the parent's zero scale hides its child's mesh too
}

TEST(GltfLoader, PlacementAppliesAfterTheNodeTransforms) {
  Scene scene;
  GltfPlacement placement;
  placement.transform = glm::scale(glm::translate(glm::mat4(1.0f), glm::vec3(0.0f, 0.0f, 10.0f)), glm::vec3(-1.0f, 1.0f, 1.0f));
  appendGltf(kGltfFixtures / "quad.gltf", kGltfFixtures, placement, scene);
  const Mesh& quad = scene.meshes[0];
  expectNear(quad.vertices[1].position, {-1.0f, 1.0f, 12.0f});
  // A mirror: the winding is reversed so that the faces still look toward the normal.
  EXPECT_EQ(quad.indices, (std::vector<std::uint32_t>{0, 2, 1, 0, 3, 2}));
  expectNear(quad.vertices[0].normal, {-1.0f, 0.0f, 0.0f});
  EXPECT_EQ(quad.vertices[0].tangent.w, -1.0f);
  const Vertex &a = quad.vertices[0], &b = quad.vertices[2], &c = quad.vertices[1];
  EXPECT_GT(glm::dot(glm::cross(b.position - a.position, c.position - a.position), a.normal), 0.0f);
}

TEST(GltfLoader, MissingNormalsAreFlatAndMissingMaterialIsTheDefault) {
  Scene scene;
  appendGltf(kGltfFixtures / "quad.gltf", kGltfFixtures, {}, scene);
  const Mesh& tri = scene.meshes[1];  // POSITION only, unsigned-byte indices, no material
  ASSERT_EQ(tri.vertices.size(), 3u);
  for (const Vertex& v : tri.vertices) expectNear(v.normal, {1.0f, 0.0f, 0.0f});
  ASSERT_EQ(scene.materials.size(), 2u);
  EXPECT_EQ(tri.material, 1);
  EXPECT_EQ(scene.materials[1].name, "quad.gltf/default");
  EXPECT_EQ(scene.materials[1].metallic, 1.0f);
  EXPECT_EQ(scene.materials[1].roughness, 1.0f);
}

// A zero NORMAL (a broken exporter's; the spec's are unit) is the faces' smooth normal: it was
// kept, and PRT's transfer, turned about no axis, drew the lower half of a sphere black.
TEST(GltfLoader, AZeroNormalIsTheFacesNormal) {
  const fs::path zero = editedQuad("zero_normal", [](nlohmann::json& g) {
    g["buffers"].push_back({{"byteLength", 48},
                            {"uri", "data:application/octet-stream;base64,"
                                    "AAAAAAAAAAAAAAAAAAAAAAAAAAAAAIA/AAAAAAAAAAAAAIA/AAAAAAAAAAAAAIA/"}});  // 0, +z, +z, +z
    g["bufferViews"].push_back({{"buffer", 1}, {"byteOffset", 0}, {"byteLength", 48}});
    g["accessors"].push_back({{"bufferView", g["bufferViews"].size() - 1}, {"componentType", 5126}, {"count", 4},
                              {"type", "VEC3"}});
    g["meshes"][0]["primitives"][0]["attributes"]["NORMAL"] = g["accessors"].size() - 1;
  });
  Scene scene;
  appendGltf(zero, zero.parent_path(), {}, scene);
  for (const Vertex& v : scene.meshes[0].vertices) expectNear(v.normal, {1.0f, 0.0f, 0.0f});  // +z turned by R_y(90°)
}

TEST(GltfLoader, MaterialFactorsAndTextures) {
  Scene scene;
  scene.textures.resize(1);  // indices are offset past what the scene already holds
  appendGltf(kGltfFixtures / "quad.gltf", kGltfFixtures, {}, scene);
  const Material& m = scene.materials[0];
  EXPECT_EQ(m.name, "quad.gltf/tiles");
  EXPECT_EQ(m.baseColour, glm::vec3(0.5f, 0.25f, 1.0f));
  EXPECT_EQ(m.metallic, 0.25f);
  EXPECT_EQ(m.roughness, 0.75f);
  EXPECT_EQ(m.baseColourTexture, 1);
  EXPECT_EQ(m.normalTexture, 2);  // the same image, linear
  EXPECT_EQ(m.metallicRoughnessTexture, -1);
  ASSERT_EQ(scene.textures.size(), 3u);
  const Image& image = scene.textures[1];
  EXPECT_TRUE(image.srgb);
  EXPECT_FALSE(scene.textures[2].srgb);
  ASSERT_EQ(image.width, 2);
  ASSERT_EQ(image.height, 2);
  // checker.png: red, green / blue, white, row 0 at the top.
  EXPECT_EQ(image.rgba, (std::vector<std::uint8_t>{255, 0, 0, 255, 0, 255, 0, 255, 0, 0, 255, 255, 255, 255, 255, 255}));
}

TEST(GltfLoader, BinaryGltfWithMatrixNode) {
  Scene scene;
  scene.materials.resize(3);
  appendGltf(kGltfFixtures / "triangle.glb", kGltfFixtures, {glm::mat4(1.0f), 2, std::nullopt}, scene);
  ASSERT_EQ(scene.meshes.size(), 1u);
  EXPECT_EQ(scene.meshes[0].material, 2);
  EXPECT_EQ(scene.materials.size(), 3u);  // overridden: none added
  ASSERT_EQ(scene.meshes[0].vertices.size(), 3u);
  expectNear(scene.meshes[0].vertices[1].position, {6.0f, 0.0f, 0.0f});  // matrix translates by 5 in x
  expectNear(scene.meshes[0].vertices[1].normal, {0.0f, 0.0f, 1.0f});
}

TEST(GltfLoader, DecodeImageRefusesWhatIsNotPngOrJpeg) {
  std::vector<std::uint8_t> gif = {'G', 'I', 'F', '8', '9', 'a'};
  try {
    decodeImage(gif, true, "x.gif");
    ADD_FAILURE() << "no Error";
  } catch (const Error& e) {
    EXPECT_STREQ(e.what(), "not a PNG or JPEG image (only PNG and JPEG are supported)");
  }
}

// A texture wider than Prism reads (16 384, what it can write), refused at its image before it is
// decoded: it rendered with exit 0, its glTexStorage2D refused and the texture empty.
TEST(GltfLoader, ATextureBeyondTheLargestSideIsRefusedAtItsImage) {
  const fs::path dir = fs::path(::testing::TempDir()) / "gltf_wide_texture";
  fs::remove_all(dir);
  fs::create_directories(dir);
  nlohmann::json gltf = nlohmann::json::parse(std::ifstream(kGltfFixtures / "quad.gltf"));
  gltf["images"][0] = {{"uri", "wide.png"}};
  std::ofstream(dir / "quad.gltf") << gltf.dump();
  imaging::PngImage(imaging::kMaxPngSide + 1, 1, {128, 128, 128}).write(dir / "wide.png");
  Scene scene;
  try {
    appendGltf(dir / "quad.gltf", dir, {}, scene);
    ADD_FAILURE() << "no Error";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("quad.gltf: /images/0: the PNG: an image of 16385 × 1 pixels; Prism reads "
                                         "1 to 16384 on each side"),
              std::string::npos)
        << e.what();
  }
}

// The Error appendGltf gives for `file` (its folder the root) into `scene`.
std::string loadError(const fs::path& file, const GltfPlacement& placement = {}, Scene scene = {}) {
  return errorOf([&] { appendGltf(file, file.parent_path(), placement, scene); });
}

// A textured material on a primitive without TEXCOORD_0 (the file's own or the scene's, by
// placement) is refused at the primitive: it rendered with exit 0, every texture collapsed to the
// colour of one texel (a new-user review: a ColorChecker of tiles as one brown square).
TEST(GltfLoader, ATexturedMaterialNeedsTexCoords) {
  fs::path file = editedQuad("gltf_no_uv", [](nlohmann::json& g) { g["meshes"][0]["primitives"][0]["attributes"].erase("TEXCOORD_0"); });
  EXPECT_EQ(loadError(file), file.string() + ": /meshes/0/primitives/0/attributes: no TEXCOORD_0, which material "
                                             "'quad.gltf/tiles' needs for its textures");
  // The scene's material in place of the file's: the same.
  file = editedQuad("gltf_no_uv", [](nlohmann::json& g) {
    g["meshes"][0]["primitives"][0]["attributes"].erase("TEXCOORD_0");
    g["meshes"][0]["primitives"][0].erase("material");
    g["materials"] = g["textures"] = g["images"] = nlohmann::json::array();
  });
  Scene placed;
  Material painted;
  painted.name = "painted";
  painted.baseColourTexture = 0;
  placed.materials.push_back(painted);
  placed.textures.resize(1);
  GltfPlacement placement;
  placement.materialOverride = 0;
  EXPECT_EQ(loadError(file, placement, placed),
            file.string() + ": /meshes/0/primitives/0/attributes: no TEXCOORD_0, which material 'painted' needs for its textures");
  // Untextured, no uv is needed: the file's second primitive has none.
  placed.materials[0].baseColourTexture = -1;
  EXPECT_NO_THROW(appendGltf(file, file.parent_path(), placement, placed));
}

// glTF's emission: emissiveFactor × emissiveTexture (sRGB) at the object's luminance times
// KHR_materials_emissive_strength (read, so a file may require it). glTF gives emission no unit:
// a file that emits, placed without one, is refused at its factor (it drew dark without a word);
// 0 leaves it dark on purpose.
TEST(GltfLoader, EmissionTakesItsFactorTextureAndStrengthAtTheObjectsLuminance) {
  auto emissive = [](double strength) {
    return [strength](nlohmann::json& g) {
      g["materials"][0]["emissiveFactor"] = {1.0, 0.5, 0.25};
      g["materials"][0]["emissiveTexture"] = {{"index", 0}};
      g["materials"][0]["extensions"]["KHR_materials_emissive_strength"] = {{"emissiveStrength", strength}};
      g["extensionsRequired"] = {"KHR_materials_emissive_strength"};  // read, so not refused
    };
  };
  const fs::path file = editedQuad("gltf_emissive", emissive(4.0));
  GltfPlacement placement;
  placement.emissionLuminance = 100.0f;
  Scene scene;
  appendGltf(file, file.parent_path(), placement, scene);
  const Material& m = scene.materials.at(0);
  EXPECT_EQ(m.emissiveFactor, glm::vec3(1.0f, 0.5f, 0.25f));
  EXPECT_EQ(m.emissiveLuminance, 400.0f);
  EXPECT_EQ(m.emissiveTexture, m.baseColourTexture);  // the same image, sRGB: one texture
  EXPECT_TRUE(m.emitsRgb());

  EXPECT_EQ(loadError(file), file.string() + ": /materials/0/emissiveFactor: the material emits light, and glTF gives "
                                             "emission no unit: give the scene's object \"emission_luminance\" (cd/m² "
                                             "of emissive white; 0 leaves it dark)");
  placement.emissionLuminance = 0.0f;
  Scene dark;
  appendGltf(file, file.parent_path(), placement, dark);
  EXPECT_FALSE(dark.materials.at(0).emitsRgb());
  EXPECT_EQ(dark.materials.at(0).emissiveTexture, -1);  // not read
  // A strength of 0, or glTF's default factor (black) under a texture, emits nothing: no unit needed.
  const fs::path off = editedQuad("gltf_emissive_off", emissive(0.0));
  EXPECT_NO_THROW(appendGltf(off, off.parent_path(), {}, scene));
  const fs::path black = editedQuad("gltf_emissive_black", [](nlohmann::json& g) {
    g["materials"][0]["emissiveTexture"] = {{"index", 0}};
  });
  EXPECT_NO_THROW(appendGltf(black, black.parent_path(), {}, scene));
  EXPECT_EQ(scene.materials.back().emissiveTexture, -1);

  // A second material that emits, which no primitive names, needs no unit and shows nothing (the
  // file was refused); its values are still checked.
  auto unusedEmitter = [](double red) {
    return [red](nlohmann::json& g) {
      g["materials"][1] = {{"name", "spare lamp"}, {"emissiveFactor", {red, 0.5, 0.25}}};
    };
  };
  Scene spare;
  const fs::path withSpare = editedQuad("gltf_emissive_unused", unusedEmitter(1.0));
  ASSERT_NO_THROW(appendGltf(withSpare, withSpare.parent_path(), {}, spare));
  ASSERT_EQ(spare.materials.at(1).name, "quad.gltf/spare lamp");
  EXPECT_FALSE(spare.materials.at(1).emitsRgb());
  EXPECT_EQ(loadError(editedQuad("gltf_emissive_unused_bad", unusedEmitter(2.0))),
            (fs::path(::testing::TempDir()) / "gltf_emissive_unused_bad" / "quad.gltf").string() +
                ": /materials/1/emissiveFactor/0: expected a number in [0, 1], got 2.0");

  EXPECT_EQ(loadError(editedQuad("gltf_emissive_negative", emissive(-1.0)), placement),
            (fs::path(::testing::TempDir()) / "gltf_emissive_negative" / "quad.gltf").string() +
                ": /materials/0/extensions/KHR_materials_emissive_strength/emissiveStrength: expected a number >= 0, got -1.0");
}

// A texture without a source (glTF allows it, for extensions Prism does not read) is said so; it
// read "no image -1 (the file has 1)".
TEST(GltfLoader, ATextureWithoutASourceIsSaidSo) {
  const fs::path file = editedQuad("gltf_no_source", [](nlohmann::json& g) { g["textures"][0] = nlohmann::json::object(); });
  EXPECT_EQ(loadError(file), file.string() + ": /textures/0: no \"source\": the texture names no image");
}

// A .gltf saved with a UTF-8 byte-order mark, which glTF forbids: said as such (it read "not a
// glTF (a .gltf is a JSON object …)").
TEST(GltfLoader, AByteOrderMarkIsSaidSo) {
  const fs::path file = editedQuad("gltf_bom", [](nlohmann::json&) {});
  const std::string text = nlohmann::json::parse(std::ifstream(file)).dump();
  std::ofstream(file) << "\xEF\xBB\xBF" << text;
  EXPECT_EQ(loadError(file),
            file.string() + ": starts with a UTF-8 byte-order mark, which glTF's JSON must not have (save it without one)");
}

// An image file that decodes to nothing (empty) is named in the error, not only its pointer.
TEST(GltfLoader, AnImageThatCannotBeLoadedIsNamed) {
  const fs::path file = editedQuad("gltf_empty_image", [](nlohmann::json& g) { g["images"][0] = {{"uri", "empty.png"}}; });
  std::ofstream(file.parent_path() / "empty.png").close();
  EXPECT_EQ(loadError(file), file.string() + ": /images/0: the image 'empty.png' could not be loaded");
}

// glTF's node hierarchy is disjoint trees (§3.5): a node reached twice — two parents, a scene's
// root listed twice or also a child — is refused where it is reached again (each drew its meshes
// twice on top of each other, exit 0; a new-user review).
TEST(GltfLoader, ANodeReachedTwiceIsRefused) {
  auto errorWith = [](const std::function<void(nlohmann::json&)>& edit) {
    const fs::path file = editedQuad("gltf_reached_twice", edit);
    return loadError(file).substr(file.string().size());
  };
  EXPECT_EQ(errorWith([](nlohmann::json& g) { g["scenes"][0]["nodes"] = {0, 0}; }),
            ": /scenes/0/nodes/1: node 0 again, already reached from /scenes/0/nodes/0 (a glTF node has one parent at "
            "most, and a scene lists root nodes only)");
  EXPECT_EQ(errorWith([](nlohmann::json& g) { g["scenes"][0]["nodes"] = {0, 1}; }),
            ": /scenes/0/nodes/1: node 1 again, already reached from /nodes/0/children/0 (a glTF node has one parent at "
            "most, and a scene lists root nodes only)");
  EXPECT_EQ(errorWith([](nlohmann::json& g) {
              g["nodes"].push_back({{"name", "second parent"}, {"children", {1}}});
              g["scenes"][0]["nodes"] = {0, 2};
            }),
            ": /nodes/2/children/0: node 1 again, already reached from /nodes/0/children/0 (a glTF node has one parent "
            "at most, and a scene lists root nodes only)");
  EXPECT_EQ(errorWith([](nlohmann::json& g) { g["nodes"][1]["children"] = {0}; }), ": /nodes/0: the node is its own ancestor");
  const fs::path file = editedQuad("gltf_reached_twice", [](nlohmann::json&) {});
  Scene scene;
  EXPECT_NO_THROW(appendGltf(file, file.parent_path(), {}, scene));
}

// A buffer's byteLength is held to its data: URI as the loader decodes it, unpadded base64
// included: 2 more characters are 1 more byte (a first count took them for none); any other
// length is said at its pointer (tinygltf quoted the whole URI).
TEST(GltfLoader, ABuffersByteLengthIsHeldToItsDataUri) {
  const fs::path dir = fs::path(::testing::TempDir()) / "gltf_byte_length";
  fs::remove_all(dir);
  fs::create_directories(dir);
  nlohmann::json gltf = nlohmann::json::parse(std::ifstream(kGltfFixtures / "quad.gltf"));
  ASSERT_EQ(gltf["buffers"][0]["byteLength"], 144);  // 192 characters
  gltf["buffers"][0]["uri"] = gltf["buffers"][0]["uri"].get<std::string>() + "AA";
  gltf["buffers"][0]["byteLength"] = 145;
  std::ofstream(dir / "unpadded.gltf") << gltf.dump();
  Scene scene;
  EXPECT_NO_THROW(appendGltf(dir / "unpadded.gltf", dir, {}, scene));
  for (int length : {144, 146}) {
    gltf["buffers"][0]["byteLength"] = length;
    std::ofstream(dir / "mismatch.gltf") << gltf.dump();
    try {
      appendGltf(dir / "mismatch.gltf", dir, {}, scene);
      ADD_FAILURE() << "no Error at " << length;
    } catch (const Error& e) {
      EXPECT_NE(std::string(e.what()).find("mismatch.gltf: /buffers/0/byteLength: " + std::to_string(length) +
                                           " bytes, but the buffer's data: URI holds 145"),
                std::string::npos)
          << e.what();
    }
  }
}

// A buffer file's size is held to its byteLength, at the glTF's place (tinygltf named neither file
// nor buffer: "File size mismatch : tiles.bin, requestedBytes 1297, but got 1296").
TEST(GltfLoader, ABuffersByteLengthIsHeldToItsFile) {
  const fs::path dir = fs::path(::testing::TempDir()) / "gltf_file_byte_length";
  fs::remove_all(dir);
  fs::create_directories(dir);
  const fs::path models = fs::path(PRISM_EXAMPLE_SCENE_DIR) / "models";
  for (const auto& entry : fs::directory_iterator(models))
    if (entry.path().filename().string().starts_with("tiles")) fs::copy_file(entry.path(), dir / entry.path().filename());
  nlohmann::json gltf = nlohmann::json::parse(std::ifstream(dir / "tiles.gltf"));
  ASSERT_EQ(gltf["buffers"][0]["byteLength"], fs::file_size(dir / "tiles.bin"));
  Scene scene;
  EXPECT_NO_THROW(appendGltf(dir / "tiles.gltf", dir, {}, scene));
  gltf["buffers"][0]["byteLength"] = fs::file_size(dir / "tiles.bin") + 1;
  std::ofstream(dir / "mismatch.gltf") << gltf.dump();
  EXPECT_EQ(errorOf([&] { appendGltf(dir / "mismatch.gltf", dir, {}, scene); }),
            (dir / "mismatch.gltf").string() +
                ": /buffers/0/byteLength: 1297 bytes, but tiles.bin holds 1296 (the loader takes them equal)");
}

// A .glb that is not a binary glTF says so (read as JSON, it was "malformed JSON").
TEST(GltfLoader, AGlbWithoutItsMagicIsNamedSo) {
  const fs::path dir = fs::path(::testing::TempDir()) / "gltf_no_magic";
  fs::create_directories(dir);
  std::ofstream(dir / "model.glb") << "GLTF garbage";
  Scene scene;
  try {
    appendGltf(dir / "model.glb", dir, {}, scene);
    ADD_FAILURE() << "no Error";
  } catch (const Error& e) {
    EXPECT_STREQ(e.what(), ((dir / "model.glb").string() + ": not a binary glTF (it does not start with \"glTF\")").c_str());
  }
}

// A JPEG's header claiming 65 000² pixels is refused from the header: it went to the decoder, whose
// RGBA would take 17 GB.
TEST(GltfLoader, AJpegBeyondTheLargestSideIsRefusedBeforeDecoding) {
  // SOI, then a baseline SOF0: 8 bits, 65 000 × 65 000, three components.
  const std::vector<std::uint8_t> jpeg = {0xFF, 0xD8, 0xFF, 0xC0, 0x00, 0x11, 0x08, 0xFD, 0xE8, 0xFD, 0xE8, 0x03,
                                          0x01, 0x22, 0x00, 0x02, 0x11, 0x01, 0x03, 0x11, 0x01};
  try {
    decodeImage(jpeg, true, "big.jpg");
    ADD_FAILURE() << "no Error";
  } catch (const Error& e) {
    EXPECT_STREQ(e.what(), "big.jpg: an image of 65000 × 65000 pixels; Prism reads 1 to 16384 on each side");
  }
}

}  // namespace
}  // namespace prism
