#include "scene/scene_loader.h"

#include <algorithm>
#include <cmath>
#include <iterator>
#include <limits>
#include <map>
#include <utility>

#include <Eigen/Core>
#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "scene/conductors.h"
#include "scene/gltf_loader.h"
#include "scene/procedural_mesh.h"
#include "imaging/spectral_texture_file.h"
#include "core/json_schema.h"
#include "spectral/colour_space.h"
#include "spectral/spectrum_csv.h"
#include "core/error.h"
#include "spectral/illuminant.h"
#include "spectral/observer.h"
#include "spectral/rgb_intent.h"
#include "techniques/registry.h"

namespace prism {

namespace {

namespace fs = std::filesystem;
using nlohmann::json;
using schema::Node;
using schema::Range;

std::string joined(const std::vector<std::string>& items) {
  std::string out;
  for (const std::string& s : items) out += (out.empty() ? "" : ", ") + s;
  return out;
}

class SceneParser {
 public:
  SceneParser(const fs::path& file, const schema::Document& document)
      : mFolder(file.parent_path().empty() ? fs::path(".") : file.parent_path()), mDocument(document) {
    mScene.file = file;
  }

  Scene parse(const json& root) {
    Node top(root, "", mDocument);
    std::vector<std::string_view> keys{"$schema", "description", "colour_space", "camera", "lights",
                                       "materials", "objects", "background"};
    for (const TechniqueSectionParser& technique : techniqueSectionParsers()) keys.emplace_back(technique.key);
    top.expectObject(keys);
    if (root.size() == 1 && root.contains("nebula"))  // said before "missing required key 'camera'"
      top.fail("a nebula scene (its only key is \"nebula\"): `prism nebula render` takes it; a scene of the renderer "
               "has a camera and objects, and may hold a nebula section");
    for (const char* key : {"$schema", "description"})
      if (auto n = top.optionalChild(key); n && !n->json().is_string())
        n->fail("expected a string, got " + schema::describe(n->json()));
    if (auto n = top.optionalChild("colour_space")) {
      const std::string name = n->string();  // its own error names the place: outside the try
      try {
        mScene.colourSpace = colourSpace(name).name;
      } catch (const Error& e) {
        n->fail(e.what());
      }
    }
    mScene.camera = camera(top.child("camera"));
    if (auto materials = top.optionalChild("materials")) {
      for (const std::string& name : materials->keys()) {
        mMaterialIndex[name] = static_cast<int>(mScene.materials.size());
        mScene.materials.push_back(material(materials->child(name), name));
      }
    }
    if (auto lights = top.optionalChild("lights"))
      for (std::size_t i = 0; i < lights->arraySize(); ++i) mScene.lights.push_back(light(lights->element(i)));
    Node objects = top.child("objects");
    for (std::size_t i = 0; i < objects.arraySize(); ++i) object(objects.element(i));
    if (auto bg = top.optionalChild("background")) {
      bg->expectObject({"colour", "luminance"});
      mScene.background = bg->vec3("colour", glm::vec3(1.0f), Range::atLeast(0.0));
      mScene.backgroundLuminance = bg->child("luminance").numberF(Range::atLeast(0.0));
    }
    for (const TechniqueSectionParser& technique : techniqueSectionParsers()) {
      if (auto n = top.optionalChild(technique.key)) mScene.techniques.add(technique.parse(*n, mScene.techniques));
    }
    // Objects shaded by a technique: it must be in the scene and shade objects (its section is
    // read after the objects, so this is checked last).
    for (const auto& [node, key] : mObjectTechniques) {
      const TechniqueSection* section = mScene.techniques.find(key);
      if (!section) {
        std::string known;  // 'PRT' was told the scene lacked a section it had, as 'prt'
        bool isTechnique = false;
        for (const TechniqueSectionParser& technique : techniqueSectionParsers()) {
          known += (known.empty() ? "" : ", ") + std::string(technique.key);
          isTechnique = isTechnique || technique.key == key;
        }
        if (!isTechnique) node.fail("'" + key + "' is no technique (known: " + known + ")");
        node.fail("the scene has no '" + key + "' section to shade this object");
      }
      if (!section->shadesObjects()) node.fail("'" + key + "' does not shade objects");
    }
    applyTechniqueLights(mScene);
    // The scene's lights reach PRT objects through the lighting pass, which reads no spectral
    // texture: such an object came out as its base colour, flat grey, without a word.
    if (!mScene.lights.empty() && !mSpectrallyTextured.empty()) {
      std::vector<std::string> remedies;
      for (const Light& light : mScene.lights) {
        const std::string remedy = light.technique.empty()      ? "give the scene no /lights"
                                   : light.technique == "prt" ? "set prt.environment.atmosphere.sun_disc to false"
                                                              : "take out the " + light.technique + " section, whose sun it is";
        if (std::ranges::find(remedies, remedy) == remedies.end()) remedies.push_back(remedy);
      }
      std::string joined = remedies.front();
      for (std::size_t i = 1; i < remedies.size(); ++i) joined += (i + 1 == remedies.size() ? " and " : ", ") + remedies[i];
      const auto& [node, name] = mSpectrallyTextured.front();
      node.fail("material '" + name + "' " + std::string(kSpectralTextureUnderLights) + "; " + joined);
    }
    return std::move(mScene);
  }

 private:
  // A file named by a string node: inside the scene's folder, existing.
  fs::path file(const Node& node) {
    std::string relative = node.string();
    try {
      return mScene.files.emplace_back(schema::confinedFile(mFolder, mFolder, relative));
    } catch (const Error& e) {
      node.fail(e.what());
    }
  }

  Camera camera(const Node& n) const {
    n.expectObject({"position", "target", "up", "fov_deg", "near", "far", "ev100"});
    Camera c;
    c.position = n.vec3("position", c.position);
    c.target = n.vec3("target", c.target);
    c.up = n.vec3("up", c.up);
    c.verticalFovDeg = n.numberF("fov_deg", c.verticalFovDeg, Range{kMinCameraFovDeg, kMaxCameraFovDeg, false, true});
    c.nearPlane = n.numberF("near", c.nearPlane, Range::above(0.0));
    c.farPlane = n.numberF("far", c.farPlane, Range::above(c.nearPlane));
    if (!n.has("far") && !(c.farPlane > c.nearPlane))
      n.child("near").fail("expected a number < far (" + schema::describe(c.farPlane) + ")");
    if (c.farPlane / c.nearPlane > kMaxFarOverNear)
      (n.has("near") ? n.child("near") : n.child("far"))
          .fail(fmt::format("far / near = {:g} is past {:g}, where depth loses the precision lighting needs: "
                            "raise near or lower far",
                            static_cast<double>(c.farPlane / c.nearPlane), static_cast<double>(kMaxFarOverNear)));
    c.ev100 = n.numberF("ev100", c.ev100, Range::closed(-kEv100Limit, kEv100Limit));
    glm::vec3 view = c.target - c.position;
    if (!(glm::length(view) > 0.0f)) (n.has("target") ? n.child("target") : n).fail("target equals position");
    if (!(glm::length(glm::cross(view, c.up)) > 1e-6f * glm::length(view) * glm::length(c.up)))
      (n.has("up") ? n.child("up") : n).fail("up must be non-zero and not parallel to target − position");
    return c;
  }

  // A light's spectrum, normalised photometrically; `label` says what the file said.
  Spectrum spd(const Node& n, std::string& label) {
    Spectrum s;
    if (n.json().is_string()) {
      label = n.string();
      try {
        s = illuminant(label);
      } catch (const Error& e) {
        n.fail(e.what());
      }
    } else {
      n.expectObject({"csv", "rgb"});
      if (n.json().size() != 1) n.fail("expected exactly one of the keys csv, rgb");
      if (auto csv = n.optionalChild("csv")) {
        fs::path path = file(*csv);
        label = "csv:" + csv->string();
        try {
          s = readLampCsv(path);
        } catch (const Error& e) {
          csv->fail(e.what());
        }
      } else {
        Node rgbNode = n.child("rgb");
        glm::vec3 rgb = rgbNode.vec3(Range::atLeast(0.0));
        if (!(std::max({rgb.r, rgb.g, rgb.b}) > 0.0f)) rgbNode.fail("expected a colour that is not black");
        label = "rgb:" + schema::describe(rgbNode.json());
        // A light colour, fitted exactly (no table at load); the normalisation below sets its level.
        s = RgbIlluminantSpectrum::fitted(colourSpace(mScene.colourSpace), rgb).toDense();
      }
    }
    try {
      return normalisedLightSpectrum(s);
    } catch (const Error& e) {
      n.fail(e.what());
    }
  }

  Light light(const Node& n) {
    if (!n.json().is_object()) n.fail("expected an object, got " + schema::describe(n.json()));
    Node typeNode = n.child("type");
    std::string type = typeNode.string();
    Light l;
    if (type == "directional") {
      n.expectObject({"type", "direction", "spd", "intensity", "shadows"});
      l.type = LightType::Directional;
    } else if (type == "point") {
      n.expectObject({"type", "position", "spd", "intensity", "shadows"});
      l.type = LightType::Point;
    } else if (type == "spot") {
      n.expectObject({"type", "position", "direction", "inner_cone_deg", "outer_cone_deg", "spd",
                      "intensity", "shadows"});
      l.type = LightType::Spot;
    } else {
      typeNode.fail("unknown light type '" + type + "' (directional, point, spot)");
    }
    if (l.type != LightType::Directional) l.position = n.child("position").vec3();
    if (l.type != LightType::Point) {
      Node d = n.child("direction");
      glm::vec3 direction = d.vec3();
      if (!(glm::length(direction) > 0.0f)) d.fail("expected a non-zero direction");
      l.direction = glm::normalize(direction);
    }
    if (l.type == LightType::Spot) {
      l.innerConeDeg = n.numberF("inner_cone_deg", l.innerConeDeg, Range::open(0.0, 90.0));
      l.outerConeDeg = n.numberF("outer_cone_deg", l.outerConeDeg, Range::open(0.0, 90.0));
      if (l.innerConeDeg > l.outerConeDeg)
        (n.has("inner_cone_deg") ? n.child("inner_cone_deg") : n)
            .fail("inner_cone_deg (" + schema::describe(l.innerConeDeg) + ") exceeds outer_cone_deg (" +
                  schema::describe(l.outerConeDeg) + ")");
    }
    l.spd = spd(n.child("spd"), l.spdLabel);
    l.intensity = n.child("intensity").numberF(Range::above(0.0));
    l.castsShadows = n.boolean("shadows", true);
    return l;
  }

  int texture(const Node& n, bool srgb) {
    fs::path path = file(n);
    std::error_code ec;
    std::string key = fs::weakly_canonical(path, ec).string() + (srgb ? "#srgb" : "#linear");
    if (auto it = mTextureIndex.find(key); it != mTextureIndex.end()) return it->second;
    Image image;
    std::vector<unsigned char> bytes;
    try {
      bytes = schema::readBinaryFile(path);
    } catch (const Error& e) {
      n.fail(e.what());
    }
    try {
      image = decodeImage(bytes, srgb, path.string());
    } catch (const Error& e) {
      const std::string why = e.what();  // the PNG checks name the file themselves
      n.fail(why.rfind(path.string() + ": ", 0) == 0 ? why : path.string() + ": " + why);
    }
    mScene.textures.push_back(std::move(image));
    int index = static_cast<int>(mScene.textures.size()) - 1;
    mTextureIndex[key] = index;
    return index;
  }

  std::shared_ptr<const SpectralTexture> spectralTexture(const Node& n) {
    fs::path path = file(n);
    std::error_code ec;
    std::string key = fs::weakly_canonical(path, ec).string();
    if (auto it = mSpectralTextures.find(key); it != mSpectralTextures.end()) return it->second;
    try {
      return mSpectralTextures[key] = std::make_shared<const SpectralTexture>(imaging::readSpectralTexture(path));
    } catch (const Error& e) {
      n.fail(e.what());
    }
  }

  // Only PRT objects shade spectral textures: the deferred pipeline reads no such texture. PRT
  // objects are diffuse by definition, so a conductor, which PRT cannot shade and the reference
  // would trace with its own spectra, is refused on them.
  void checkTechniqueMaterial(const Node& o, int material, const std::string& technique) {
    const Material& m = mScene.materials.at(static_cast<std::size_t>(material));
    if (m.spectralTexture && technique != "prt")
      o.fail("material '" + m.name + "' has a spectral texture, which only PRT objects (\"technique\": \"prt\") shade");
    if (m.spectralTexture) mSpectrallyTextured.emplace_back(o, m.name);
    if (m.conductor && technique == "prt")
      o.fail("material '" + m.name + "' is a conductor, which PRT objects (diffuse by definition) cannot shade");
    if (m.emission && technique == "prt")
      o.fail("material '" + m.name + "' emits light, which PRT objects (lit by their transfer alone) do not show");
  }

  Material material(const Node& n, const std::string& name) {
    n.expectObject({"base_colour", "base_colour_srgb", "metallic", "roughness", "lambertian",
                    "reflectance", "conductor", "base_colour_texture", "metallic_roughness_texture", "normal_texture",
                    "spectral_texture", "emission"});
    Material m;
    m.name = name;
    if (n.has("base_colour") && n.has("base_colour_srgb"))
      n.child("base_colour_srgb").fail("give base_colour or base_colour_srgb, not both");
    if (auto c = n.optionalChild("base_colour")) m.baseColour = c->vec3(Range::closed(0.0, 1.0));
    if (auto c = n.optionalChild("base_colour_srgb")) {
      // IEC 61966-2-1 decoding (spectral/colour_space.h, the one implementation), then from
      // sRGB primaries to the scene's (Bradford-adapted where the whites differ).
      glm::vec3 encoded = c->vec3(Range::closed(0.0, 1.0));
      const RgbColourSpace& srgb = colourSpace("srgb");
      Eigen::Vector3d linear = srgb.decode(Eigen::Vector3d(encoded.r, encoded.g, encoded.b));
      linear = rgbToRgb(srgb, colourSpace(mScene.colourSpace)) * linear;
      for (int i = 0; i < 3; ++i) m.baseColour[i] = static_cast<float>(std::clamp(linear[i], 0.0, 1.0));
    }
    m.metallic = n.numberF("metallic", m.metallic, Range::closed(0.0, 1.0));
    m.roughness = n.numberF("roughness", m.roughness, Range::closed(0.0, 1.0));
    m.lambertian = n.boolean("lambertian", false);
    if (auto r = n.optionalChild("reflectance")) {
      r->expectObject({"csv"});
      Node csv = r->child("csv");
      fs::path path = file(csv);
      try {
        // Reflectances: the last measured value is the best estimate of the next.
        m.reflectance = readSpectrumCsv(path, Extrapolation::Clamp, 0.0, 1.0).toDense();
      } catch (const Error& e) {
        csv.fail(e.what());
      }
    }
    if (auto c = n.optionalChild("conductor")) {
      // Its colour and its metalness are its n and k: anything else saying them was ignored.
      for (const char* other : {"base_colour", "base_colour_srgb", "reflectance", "base_colour_texture", "metallic"})
        if (n.has(other))
          n.child(other).fail(std::string("a conductor's colour and metalness are its measured n and k: give ") + other +
                              " or conductor, not both");
      const std::string metal = c->string();  // its own error names the place: outside the try
      try {
        m.conductor = conductorIor(metal);
      } catch (const Error& e) {
        c->fail(e.what());
      }
    }
    // Lambertian is all of the light diffused: a metal has none to diffuse (the surface came out
    // black, or darkened by 1 − metallic, with no word).
    if (m.lambertian) {
      if (m.metallic > 0.0f) n.child("metallic").fail("a lambertian material diffuses all of the light: metallic must be 0, or drop lambertian");
      for (const char* other : {"conductor", "metallic_roughness_texture"})
        if (n.has(other))
          n.child(other).fail(std::string("a lambertian material diffuses all of the light: give ") + other +
                              " or lambertian, not both");
    }
    if (auto e = n.optionalChild("emission")) {
      // As a light's: its spectrum (any of a light's "spd" forms), normalised, times its luminance.
      e->expectObject({"spd", "luminance"});
      std::string label;
      Emission emission;
      emission.spd = spd(e->child("spd"), label);
      emission.luminance = e->child("luminance").numberF(Range::above(0.0));
      m.emission = std::move(emission);
    }
    if (auto t = n.optionalChild("base_colour_texture")) m.baseColourTexture = texture(*t, true);
    if (auto t = n.optionalChild("metallic_roughness_texture")) m.metallicRoughnessTexture = texture(*t, false);
    if (auto t = n.optionalChild("normal_texture")) m.normalTexture = texture(*t, false);
    if (auto t = n.optionalChild("spectral_texture")) {
      for (const char* other : {"base_colour", "base_colour_srgb", "reflectance", "conductor", "base_colour_texture"})
        if (n.has(other)) t->fail(std::string("a spectral texture is the reflectance: give it or ") + other + ", not both");
      m.spectralTexture = spectralTexture(*t);
    }
    return m;
  }

  int materialReference(const Node& n) const {
    std::string name = n.string();
    auto it = mMaterialIndex.find(name);
    if (it == mMaterialIndex.end()) {
      std::vector<std::string> names;
      for (const auto& [known, index] : mMaterialIndex) names.push_back(known);
      n.fail("unknown material '" + name + "' (materials: " + (names.empty() ? "none" : joined(names)) + ")");
    }
    return it->second;
  }

  glm::mat4 transform(const Node& n) const {
    n.expectObject({"translation", "rotation_deg", "scale"});
    glm::vec3 scale(1.0f);
    if (auto s = n.optionalChild("scale")) {
      scale = s->json().is_number() ? glm::vec3(s->numberF()) : s->vec3();
      if (scale.x == 0.0f || scale.y == 0.0f || scale.z == 0.0f) s->fail("a scale must not be zero");
    }
    return trsMatrix(n.vec3("translation", glm::vec3(0.0f)), n.vec3("rotation_deg", glm::vec3(0.0f)), scale);
  }

  void object(const Node& o) {
    if (!o.json().is_object()) o.fail("expected an object, got " + schema::describe(o.json()));
    std::vector<std::string> kinds;
    for (const char* k : {"sphere", "plane", "box", "heightfield", "gltf"})
      if (o.has(k)) kinds.push_back(k);
    if (kinds.size() != 1)
      o.fail(kinds.empty() ? "expected one of the keys sphere, plane, box, heightfield, gltf"
                           : "expected only one of the keys sphere, plane, box, heightfield, gltf, got " + joined(kinds));
    const std::string& kind = kinds[0];
    std::string name = o.has("name") ? o.child("name").string() : o.pointer();
    std::string technique;
    if (auto t = o.optionalChild("technique")) {
      technique = t->string();
      mObjectTechniques.emplace_back(*t, technique);
    }

    if (kind == "gltf") {
      o.expectObject({"gltf", "transform", "material", "emission_luminance", "name", "technique"});
      Node g = o.child("gltf");
      fs::path path = file(g);
      GltfPlacement placement;
      if (auto t = o.optionalChild("transform")) placement.transform = transform(*t);
      if (auto l = o.optionalChild("emission_luminance")) {
        if (o.has("material")) l->fail("the object's \"material\" replaces the file's, whose emission this would set");
        placement.emissionLuminance = l->numberF(Range::atLeast(0.0));
      }
      if (auto m = o.optionalChild("material")) {
        placement.materialOverride = materialReference(*m);
        checkTechniqueMaterial(o, placement.materialOverride, technique);
      }
      std::size_t first = mScene.meshes.size();
      try {
        appendGltf(path, mFolder, placement, mScene);
        for (std::size_t i = first; i < mScene.meshes.size(); ++i) mScene.meshes[i].technique = technique;
      } catch (const Error& e) {
        g.fail(e.what());
      }
      if (technique == "prt")
        for (std::size_t i = first; i < mScene.meshes.size(); ++i)
          if (const Material& m = mScene.materials.at(static_cast<std::size_t>(mScene.meshes[i].material)); m.emitsRgb())
            o.child("emission_luminance")
                .fail("material '" + m.name + "' emits light, which PRT objects (lit by their transfer alone) do not show");
      // The nodes' transforms times the object's: a vertex must land within the scene's ±1e12.
      for (std::size_t i = first; i < mScene.meshes.size(); ++i)
        for (const Vertex& v : mScene.meshes[i].vertices)
          if (!(glm::all(glm::lessThanEqual(glm::abs(v.position), glm::vec3(static_cast<float>(schema::kFloatInputLimit))))))
            (o.has("transform") ? o.child("transform") : g)
                .fail(fmt::format("a vertex lands at ({}, {}, {}) once placed: past ±1e12", v.position.x, v.position.y,
                                  v.position.z));
      return;
    }

    o.expectObject({kind, "material", "name", "technique"});
    Node shape = o.child(kind);
    Mesh mesh;
    if (kind == "sphere") {
      shape.expectObject({"centre", "radius", "segments"});
      mesh = makeSphere(shape.child("centre").vec3(), shape.child("radius").numberF(Range::above(0.0)),
                        shape.has("segments") ? shape.child("segments").integer(Range::closed(3, 4096)) : 64);
    } else if (kind == "plane") {
      shape.expectObject({"centre", "normal", "size"});
      Node normal = shape.child("normal");
      glm::vec3 nv = normal.vec3();
      if (!(glm::length(nv) > 0.0f)) normal.fail("expected a non-zero normal");
      mesh = makePlane(shape.child("centre").vec3(), nv, shape.child("size").vec2(Range::above(0.0)));
    } else if (kind == "heightfield") {
      shape.expectObject({"centre", "size", "resolution", "amplitude", "feature_size", "seed", "texture_tile"});
      mesh = makeHeightField(shape.child("centre").vec3(), shape.child("size").vec2(Range::above(0.0)),
                             shape.has("resolution") ? shape.child("resolution").integer(Range::closed(1, 2048)) : 128,
                             shape.numberF("amplitude", 0.5f, Range::atLeast(0.0)),
                             shape.numberF("feature_size", 4.0f, Range::atLeast(1e-3)),
                             static_cast<std::uint32_t>(shape.has("seed") ? shape.child("seed").integer(Range::closed(0, 1e9)) : 1),
                             shape.numberF("texture_tile", 1.0f, Range::atLeast(1e-3)));
    } else {
      shape.expectObject({"centre", "size", "rotation_deg"});
      mesh = makeBox(shape.child("centre").vec3(), shape.child("size").vec3(Range::above(0.0)),
                     shape.vec3("rotation_deg", glm::vec3(0.0f)));
    }
    mesh.name = name;
    mesh.technique = technique;
    mesh.material = materialReference(o.child("material"));
    checkTechniqueMaterial(o, mesh.material, technique);
    mScene.meshes.push_back(std::move(mesh));
  }

  fs::path mFolder;
  const schema::Document& mDocument;
  Scene mScene;
  std::map<std::string, int> mMaterialIndex;
  std::map<std::string, int> mTextureIndex;
  std::map<std::string, std::shared_ptr<const SpectralTexture>> mSpectralTextures;  // by canonical path
  std::vector<std::pair<Node, std::string>> mObjectTechniques;  // an object's `technique` and its node
  std::vector<std::pair<Node, std::string>> mSpectrallyTextured;  // a PRT object's node, its material's name
};

// Applies one "PATH=VALUE" override to the parsed document (scene_loader.h).
void applyOverride(json& root, const std::string& set, schema::Document& document) {
  auto failAt = [&](const std::string& pointer, const std::string& what) {
    throw Error(document.name + ": " + (pointer.empty() ? "/" : pointer) + ": --set " + excerpt(set) + ": " + what);
  };
  std::size_t eq = set.find('=');
  if (eq == std::string::npos || eq == 0) failAt("", "expected PATH=VALUE, e.g. camera.ev100=2");
  std::string path = set.substr(0, eq), text = set.substr(eq + 1);
  json value = json::parse(
      text,
      [&](int depth, json::parse_event_t, json&) {
        if (depth >= schema::kMaxJsonDepth)
          failAt("", "the value nests deeper than " + std::to_string(schema::kMaxJsonDepth) + " levels");
        return true;
      },
      /*allow_exceptions=*/false);
  if (value.is_discarded()) value = text;

  std::vector<std::string> segments;
  for (std::size_t start = 0;;) {
    std::size_t dot = path.find('.', start);
    segments.push_back(path.substr(start, dot == std::string::npos ? std::string::npos : dot - start));
    if (segments.back().empty()) failAt("", "empty step in the path '" + path + "'");
    if (dot == std::string::npos) break;
    start = dot + 1;
  }

  json* at = &root;
  std::string pointer;
  for (std::size_t s = 0; s < segments.size(); ++s) {
    const std::string& step = segments[s];
    bool last = s + 1 == segments.size();
    if (at->is_object()) {
      std::string child = pointer + "/" + schema::pointerToken(step);
      if (!at->contains(step)) {
        if (!last) {
          std::vector<std::string> keys;
          for (const auto& item : at->items()) keys.push_back(item.key());
          failAt(child, "no such key (here: " + (keys.empty() ? std::string("none") : joined(keys)) + ")");
        }
        (*at)[step] = value;
        document.setOnCommandLine.insert(child);
        return;
      }
      at = &(*at)[step];
      pointer = child;
    } else if (at->is_array()) {
      bool digits = std::all_of(step.begin(), step.end(), [](char c) { return c >= '0' && c <= '9'; });
      if (!digits || step.size() > 9 || std::stoul(step) >= at->size())
        failAt(pointer + "/" + step, "no element " + step + " (the array has " + std::to_string(at->size()) + ")");
      at = &(*at)[std::stoul(step)];
      pointer += "/" + std::to_string(std::stoul(step));  // as the loader names it: "01" is /1
    } else {
      failAt(pointer, "cannot look up '" + step + "' in " + schema::describe(*at));
    }
  }
  *at = value;
  document.setOnCommandLine.insert(pointer);
}

}  // namespace

Spectrum normalisedLightSpectrum(const Spectrum& spd) {
  for (int i = 0; i < kSpectrumSamples; ++i)
    if (!(spd[i] >= 0.0) || !std::isfinite(spd[i])) throw Error("the spectrum has negative or non-finite values");
  double luminous = luminousIntegral(spd);
  if (!(luminous > 0.0) || !std::isfinite(luminous))
    throw Error("the spectrum has no luminous power (683 lm/W · ∫ S ȳ dλ = 0 over 360–830 nm)");
  return spd * (1.0 / luminous);
}

void applyTechniqueLights(Scene& scene) {
  for (const auto& section : scene.techniques.all()) {
    const std::optional<TechniqueLight> l = section->light();
    if (!l) {  // switched off (PRT's sun disc): its light goes
      std::erase_if(scene.lights, [&](const Light& light) { return light.technique == section->key(); });
      continue;
    }
    auto light = std::ranges::find(scene.lights, section->key(), &Light::technique);
    if (light == scene.lights.end()) {  // on load, or switched on
      Light added;
      added.type = LightType::Directional;
      added.castsShadows = l->castsShadows;
      added.technique = std::string(section->key());
      scene.lights.push_back(std::move(added));
      light = std::prev(scene.lights.end());
    } else if (!l->followsSection) {
      light->direction = l->direction;  // its spectrum and intensity are the user's to edit
      continue;
    }
    light->direction = l->direction;
    light->intensity = static_cast<float>(l->illuminanceLux >= 0.0 ? l->illuminanceLux : luminousIntegral(l->spd));
    light->spd = normalisedLightSpectrum(l->spd);
    light->spdLabel = l->spdLabel;
  }
}

Scene loadScene(const fs::path& file) { return loadScene(file, {}); }

Scene loadScene(const fs::path& file, const std::vector<std::string>& sets) {
  schema::Document document{file.string(), {}};
  std::error_code ec;
  if (fs::is_directory(file, ec)) throw Error(document.name + ": is a folder, not a scene file");
  if (fs::exists(file, ec) && !fs::is_regular_file(file, ec))
    throw Error(document.name + ": not a regular file (a device, a pipe or a socket), not a scene file");
  if (!fs::is_regular_file(file, ec)) throw Error(document.name + ": scene file not found");
  std::vector<unsigned char> bytes = schema::readBinaryFile(file);
  json root = schema::parseJson(std::string_view(reinterpret_cast<const char*>(bytes.data()), bytes.size()),
                                document.name);
  for (const std::string& set : sets) applyOverride(root, set, document);
  return SceneParser(file, document).parse(root);
}

}  // namespace prism
