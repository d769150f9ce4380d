#include "scene/gltf_loader.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstring>
#include <functional>
#include <limits>
#include <map>
#include <utility>

#include <glm/gtc/quaternion.hpp>
#include <glm/gtc/type_ptr.hpp>

#include "scene/gltf_input.h"
#include "scene/procedural_mesh.h"
#include "core/json_schema.h"
#include "core/error.h"

namespace prism {

namespace {

namespace fs = std::filesystem;
using schema::Node;

// ---------------------------------------------------------------------------------------------
// The model, converted

class Converter {
 public:
  Converter(const tinygltf::Model& model, std::string name, const GltfPlacement& placement, Scene& scene)
      : mModel(model), mName(std::move(name)), mPlacement(placement), mScene(scene) {}

  void run() {
    // Materials no primitive names (a file's leftovers) are checked as the others, but an unused
    // one that emits needs no unit and shows nothing: the file loads without one.
    mUsedMaterials.assign(mModel.materials.size(), false);
    for (const tinygltf::Mesh& mesh : mModel.meshes)
      for (const tinygltf::Primitive& primitive : mesh.primitives)
        if (primitive.material >= 0 && static_cast<std::size_t>(primitive.material) < mUsedMaterials.size())
          mUsedMaterials[static_cast<std::size_t>(primitive.material)] = true;
    if (mPlacement.materialOverride < 0)
      for (std::size_t i = 0; i < mModel.materials.size(); ++i) mMaterials.push_back(material(static_cast<int>(i)));
    for (const auto& [root, pointer] : roots()) visit(root, glm::mat4(1.0f), pointer);
  }

 private:
  [[noreturn]] void fail(const std::string& pointer, const std::string& what) const {
    throw Error(mName + ": " + pointer + ": " + what);
  }

  static std::string str(std::size_t i) { return std::to_string(i); }

  template <typename T>
  const T& item(const std::vector<T>& list, int index, const char* section, const std::string& from) const {
    if (index < 0 || static_cast<std::size_t>(index) >= list.size())
      fail(from, "no " + std::string(section) + " " + std::to_string(index) + " (the file has " +
                     str(list.size()) + ")");
    return list[static_cast<std::size_t>(index)];
  }

  double factor(double value, const std::string& pointer) const {
    if (!std::isfinite(value) || value < 0.0 || value > 1.0)
      fail(pointer, "expected a number in [0, 1], got " + schema::describe(value));
    return value;
  }

  // ---- materials and textures

  template <typename Info>
  int texture(const Info& info, const std::string& pointer, bool srgb) {
    if (info.index < 0) return -1;
    if (info.texCoord != 0)
      fail(pointer + "/texCoord", "only TEXCOORD_0 is supported, got " + std::to_string(info.texCoord));
    const tinygltf::Texture& tex = item(mModel.textures, info.index, "texture", pointer + "/index");
    std::string texturePointer = "/textures/" + std::to_string(info.index);
    if (tex.source < 0) fail(texturePointer, "no \"source\": the texture names no image");
    const tinygltf::Image& src = item(mModel.images, tex.source, "image", texturePointer + "/source");
    auto key = std::make_pair(tex.source, srgb);
    if (auto it = mTextures.find(key); it != mTextures.end()) return it->second;
    std::string imagePointer = "/images/" + std::to_string(tex.source);
    if (src.image.empty())
      fail(imagePointer, src.uri.empty() ? std::string("the image could not be loaded")
                                         : "the image '" + src.uri + "' could not be loaded");
    Image image;
    try {
      image = toImage(src, srgb, mName + " " + imagePointer);
    } catch (const Error& e) {
      fail(imagePointer, e.what());
    }
    mScene.textures.push_back(std::move(image));
    int index = static_cast<int>(mScene.textures.size()) - 1;
    mTextures[key] = index;
    return index;
  }

  int material(int index) {
    const tinygltf::Material& m = mModel.materials[static_cast<std::size_t>(index)];
    std::string at = "/materials/" + std::to_string(index);
    std::string pbr = at + "/pbrMetallicRoughness";
    const tinygltf::PbrMetallicRoughness& p = m.pbrMetallicRoughness;
    Material out;
    out.name = fs::path(mName).filename().string() + "/" + (m.name.empty() ? std::to_string(index) : m.name);
    if (p.baseColorFactor.size() != 4)
      fail(pbr + "/baseColorFactor", "expected 4 numbers, got " + str(p.baseColorFactor.size()));
    for (int c = 0; c < 4; ++c) {
      double v = factor(p.baseColorFactor[static_cast<std::size_t>(c)], pbr + "/baseColorFactor/" + std::to_string(c));
      if (c < 3) out.baseColour[c] = static_cast<float>(v);
    }
    out.metallic = static_cast<float>(factor(p.metallicFactor, pbr + "/metallicFactor"));
    out.roughness = static_cast<float>(factor(p.roughnessFactor, pbr + "/roughnessFactor"));
    if (!std::isfinite(m.normalTexture.scale))
      fail(at + "/normalTexture/scale", "expected a finite number, got " + schema::describe(m.normalTexture.scale));
    out.baseColourTexture = texture(p.baseColorTexture, pbr + "/baseColorTexture", true);
    out.metallicRoughnessTexture = texture(p.metallicRoughnessTexture, pbr + "/metallicRoughnessTexture", false);
    out.normalTexture = texture(m.normalTexture, at + "/normalTexture", false);
    emission(m, index, at, out);
    mScene.materials.push_back(std::move(out));
    return static_cast<int>(mScene.materials.size()) - 1;
  }

  // emissiveFactor × emissiveTexture at the placement's luminance times
  // KHR_materials_emissive_strength. glTF gives emission no unit, so a material that emits needs
  // the scene to give one: without it the file is refused rather than drawn dark without a word.
  void emission(const tinygltf::Material& m, int index, const std::string& at, Material& out) {
    if (m.emissiveFactor.size() != 3)
      fail(at + "/emissiveFactor", "expected 3 numbers, got " + str(m.emissiveFactor.size()));
    for (int c = 0; c < 3; ++c)
      out.emissiveFactor[c] = static_cast<float>(
          factor(m.emissiveFactor[static_cast<std::size_t>(c)], at + "/emissiveFactor/" + std::to_string(c)));
    double strength = 1.0;
    if (auto it = m.extensions.find("KHR_materials_emissive_strength"); it != m.extensions.end()) {
      std::string pointer = at + "/extensions/KHR_materials_emissive_strength/emissiveStrength";
      const tinygltf::Value& e = it->second;
      if (e.Has("emissiveStrength")) strength = e.Get("emissiveStrength").GetNumberAsDouble();
      if (!std::isfinite(strength) || strength < 0.0 || strength > schema::kFloatInputLimit)
        fail(pointer, "expected a number in [0, 1e+12], got " + schema::describe(strength));
    }
    bool emits = strength > 0.0 && std::max({out.emissiveFactor.r, out.emissiveFactor.g, out.emissiveFactor.b}) > 0.0f;
    if (!emits || !mUsedMaterials[static_cast<std::size_t>(index)]) return;
    if (!mPlacement.emissionLuminance)
      fail(at + "/emissiveFactor",
           "the material emits light, and glTF gives emission no unit: give the scene's object \"emission_luminance\" "
           "(cd/m² of emissive white; 0 leaves it dark)");
    const double luminance = static_cast<double>(*mPlacement.emissionLuminance) * strength;
    if (!(luminance <= schema::kFloatInputLimit))
      fail(at + "/extensions/KHR_materials_emissive_strength/emissiveStrength",
           "times the object's emission_luminance gives " + schema::describe(luminance) + " cd/m²: past 1e+12");
    if (!(luminance > 0.0)) return;  // dark on purpose: its texture is not read
    out.emissiveLuminance = static_cast<float>(luminance);
    out.emissiveTexture = texture(m.emissiveTexture, at + "/emissiveTexture", true);
  }

  // glTF 2.0 §3.9.1: a primitive without a material gets the default one (white, fully
  // metallic, fully rough).
  int defaultMaterial() {
    if (mDefaultMaterial < 0) {
      Material m;
      m.name = fs::path(mName).filename().string() + "/default";
      m.baseColour = glm::vec3(1.0f);
      m.metallic = 1.0f;
      m.roughness = 1.0f;
      mScene.materials.push_back(std::move(m));
      mDefaultMaterial = static_cast<int>(mScene.materials.size()) - 1;
    }
    return mDefaultMaterial;
  }

  // ---- the node tree

  // Root nodes, each with the pointer that names it.
  std::vector<std::pair<int, std::string>> roots() const {
    std::vector<std::pair<int, std::string>> out;
    if (!mModel.scenes.empty()) {
      int s = mModel.defaultScene >= 0 ? mModel.defaultScene : 0;
      const std::vector<int>& nodes = item(mModel.scenes, s, "scene", "/scene").nodes;
      for (std::size_t i = 0; i < nodes.size(); ++i)
        out.emplace_back(nodes[i], "/scenes/" + std::to_string(s) + "/nodes/" + str(i));
      return out;
    }
    // No scenes: every node that is nobody's child (glTF 2.0 §3.5.1 leaves this to the client).
    std::vector<bool> isChild(mModel.nodes.size(), false);
    for (const tinygltf::Node& n : mModel.nodes)
      for (int c : n.children)
        if (c >= 0 && static_cast<std::size_t>(c) < isChild.size()) isChild[static_cast<std::size_t>(c)] = true;
    for (std::size_t i = 0; i < isChild.size(); ++i)
      if (!isChild[i]) out.emplace_back(static_cast<int>(i), "/nodes/" + str(i));
    return out;
  }

  std::vector<float> finite(const std::vector<double>& values, std::size_t n, const std::string& pointer) const {
    if (values.size() != n) fail(pointer, "expected " + str(n) + " numbers, got " + str(values.size()));
    std::vector<float> out;
    for (std::size_t i = 0; i < n; ++i) {
      if (!(std::abs(values[i]) <= schema::kFloatInputLimit))
        fail(pointer + "/" + str(i), "expected a number within ±1e12, got " + schema::describe(values[i]));
      out.push_back(static_cast<float>(values[i]));
    }
    return out;
  }

  glm::mat4 localMatrix(const tinygltf::Node& node, const std::string& at) const {
    if (!node.matrix.empty()) return glm::make_mat4(finite(node.matrix, 16, at + "/matrix").data());  // column-major, as glTF
    glm::mat4 m(1.0f);
    if (!node.translation.empty()) {
      std::vector<float> t = finite(node.translation, 3, at + "/translation");
      m = glm::translate(m, glm::vec3(t[0], t[1], t[2]));
    }
    if (!node.rotation.empty()) {
      std::vector<float> q = finite(node.rotation, 4, at + "/rotation");  // x, y, z, w
      glm::quat r(q[3], q[0], q[1], q[2]);
      if (!(glm::length(r) > 0.0f)) fail(at + "/rotation", "the quaternion is zero");
      m *= glm::mat4_cast(glm::normalize(r));
    }
    if (!node.scale.empty()) {
      std::vector<float> s = finite(node.scale, 3, at + "/scale");
      m = glm::scale(m, glm::vec3(s[0], s[1], s[2]));
    }
    return m;
  }

  void visit(int index, const glm::mat4& parent, const std::string& from) {
    const tinygltf::Node& node = item(mModel.nodes, index, "node", from);
    std::string at = "/nodes/" + std::to_string(index);
    if (mOnPath.size() < mModel.nodes.size()) mOnPath.resize(mModel.nodes.size(), false);
    if (mReachedFrom.size() < mModel.nodes.size()) mReachedFrom.resize(mModel.nodes.size());
    if (mOnPath[static_cast<std::size_t>(index)]) fail(at, "the node is its own ancestor");
    // glTF 2.0 §3.5: disjoint trees, a node with one parent at most, a scene listing roots only. A
    // node reached twice (two parents, a root listed twice or also a child) drew its meshes twice.
    std::string& first = mReachedFrom[static_cast<std::size_t>(index)];
    if (!first.empty())
      fail(from, "node " + std::to_string(index) + " again, already reached from " + first +
                     " (a glTF node has one parent at most, and a scene lists root nodes only)");
    first = from;
    mOnPath[static_cast<std::size_t>(index)] = true;
    glm::mat4 world = parent * localMatrix(node, at);
    // A zero scale (a node hidden by its transform) draws nothing: skipped with what hangs below
    // it, rather than collapsed to triangles without area or normals.
    if (glm::determinant(glm::mat3(world)) == 0.0f) {
      mOnPath[static_cast<std::size_t>(index)] = false;
      return;
    }
    if (node.mesh >= 0) {
      const tinygltf::Mesh& mesh = item(mModel.meshes, node.mesh, "mesh", at + "/mesh");
      for (std::size_t p = 0; p < mesh.primitives.size(); ++p)
        appendPrimitive(mesh, node.mesh, p, world);
    }
    for (std::size_t c = 0; c < node.children.size(); ++c)
      visit(node.children[c], world, at + "/children/" + str(c));
    mOnPath[static_cast<std::size_t>(index)] = false;
  }

  // ---- accessors

  struct View {
    const unsigned char* data = nullptr;
    std::size_t stride = 0;
    std::size_t count = 0;
    int componentType = 0;
    int components = 0;
    bool normalized = false;
  };

  View view(int index, const std::string& from) const {
    const tinygltf::Accessor& a = item(mModel.accessors, index, "accessor", from);
    std::string at = "/accessors/" + std::to_string(index);
    if (a.sparse.isSparse) fail(at + "/sparse", "sparse accessors are not supported");
    View v;
    v.count = a.count;
    v.componentType = a.componentType;
    v.components = tinygltf::GetNumComponentsInType(static_cast<std::uint32_t>(a.type));
    v.normalized = a.normalized;
    int componentSize = tinygltf::GetComponentSizeInBytes(static_cast<std::uint32_t>(a.componentType));
    if (v.components <= 0 || componentSize <= 0) fail(at, "invalid type or componentType");
    std::size_t elementSize = static_cast<std::size_t>(v.components) * static_cast<std::size_t>(componentSize);
    // glTF 2.0 §3.6.2.1: without a bufferView the accessor is all zeros unless a sparse
    // substitution (unsupported here) fills it: nothing a renderer can use.
    if (a.bufferView < 0) fail(at, "an accessor without a bufferView (all zeros) is not supported");
    const tinygltf::BufferView& bv = item(mModel.bufferViews, a.bufferView, "bufferView", at + "/bufferView");
    std::string bvAt = "/bufferViews/" + std::to_string(a.bufferView);
    const tinygltf::Buffer& buffer = item(mModel.buffers, bv.buffer, "buffer", bvAt + "/buffer");
    v.stride = bv.byteStride != 0 ? bv.byteStride : elementSize;
    if (v.stride < elementSize) fail(bvAt + "/byteStride", "smaller than an element (" + str(elementSize) + " bytes)");
    // Every test is written so that it cannot overflow: sizes come from the file.
    if (bv.byteLength > buffer.data.size() || bv.byteOffset > buffer.data.size() - bv.byteLength)
      fail(bvAt, "reaches past the end of buffer " + std::to_string(bv.buffer) + " (" + str(buffer.data.size()) + " bytes)");
    std::size_t available = a.byteOffset <= bv.byteLength ? bv.byteLength - a.byteOffset : 0;
    if (a.byteOffset > bv.byteLength ||
        (v.count > 0 && (available < elementSize || v.count - 1 > (available - elementSize) / v.stride)))
      fail(at, "reaches past the end of bufferView " + std::to_string(a.bufferView));
    v.data = buffer.data.data() + bv.byteOffset + a.byteOffset;
    return v;
  }

  template <typename T>
  static T load(const unsigned char* p) {
    T value;
    std::memcpy(&value, p, sizeof(T));
    return value;
  }

  // Component c of element i as a float; normalized integers mapped to [0, 1] or [−1, 1]
  // (glTF 2.0 §3.11, "Animations" table of normalisation equations).
  static float component(const View& v, std::size_t i, int c) {
    int size = tinygltf::GetComponentSizeInBytes(static_cast<std::uint32_t>(v.componentType));
    const unsigned char* p = v.data + i * v.stride + static_cast<std::size_t>(c * size);
    switch (v.componentType) {
      case TINYGLTF_COMPONENT_TYPE_FLOAT: return load<float>(p);
      case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: return v.normalized ? load<std::uint8_t>(p) / 255.0f : load<std::uint8_t>(p);
      case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: return v.normalized ? load<std::uint16_t>(p) / 65535.0f : load<std::uint16_t>(p);
      case TINYGLTF_COMPONENT_TYPE_BYTE: return v.normalized ? std::max(load<std::int8_t>(p) / 127.0f, -1.0f) : load<std::int8_t>(p);
      case TINYGLTF_COMPONENT_TYPE_SHORT: return v.normalized ? std::max(load<std::int16_t>(p) / 32767.0f, -1.0f) : load<std::int16_t>(p);
      case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT: return static_cast<float>(load<std::uint32_t>(p));
      default: return 0.0f;
    }
  }

  // An attribute as vec4s (missing components 0), after checking its type against glTF 2.0
  // §3.7.2.1's table.
  std::vector<glm::vec4> attribute(const tinygltf::Primitive& prim, const char* name, int components,
                                   bool allowNormalizedUnsigned, const std::string& primAt,
                                   std::size_t expectedCount) const {
    std::vector<glm::vec4> out;
    auto it = prim.attributes.find(name);
    if (it == prim.attributes.end()) return out;
    std::string from = primAt + "/attributes/" + name;
    View v = view(it->second, from);
    std::string at = "/accessors/" + std::to_string(it->second);
    bool typeOk = v.components == components &&
                  (v.componentType == TINYGLTF_COMPONENT_TYPE_FLOAT ||
                   (allowNormalizedUnsigned && v.normalized &&
                    (v.componentType == TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE ||
                     v.componentType == TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT)));
    if (!typeOk)
      fail(at, std::string(name) + " must be " + (components == 2 ? "VEC2" : components == 3 ? "VEC3" : "VEC4") +
                   " of floats" + (allowNormalizedUnsigned ? " or normalized unsigned bytes or shorts" : ""));
    if (expectedCount != 0 && v.count != expectedCount)
      fail(at, std::string(name) + " has " + str(v.count) + " elements, POSITION has " + str(expectedCount));
    out.resize(v.count, glm::vec4(0.0f));
    for (std::size_t i = 0; i < v.count; ++i) {
      for (int c = 0; c < components; ++c) {
        float x = component(v, i, c);
        if (!std::isfinite(x)) fail(at, std::string(name) + " element " + str(i) + " is not finite");
        out[i][c] = x;
      }
    }
    return out;
  }

  std::vector<std::uint32_t> indices(const tinygltf::Primitive& prim, const std::string& primAt,
                                     std::size_t vertexCount) const {
    std::vector<std::uint32_t> out;
    if (prim.indices < 0) {
      for (std::size_t i = 0; i < vertexCount; ++i) out.push_back(static_cast<std::uint32_t>(i));
      return out;
    }
    View v = view(prim.indices, primAt + "/indices");
    std::string at = "/accessors/" + std::to_string(prim.indices);
    if (v.components != 1 || v.normalized ||
        (v.componentType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE &&
         v.componentType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT &&
         v.componentType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT))
      fail(at, "indices must be SCALAR unsigned bytes, shorts or ints");
    for (std::size_t i = 0; i < v.count; ++i) {
      auto index = static_cast<std::uint32_t>(component(v, i, 0));
      if (v.componentType == TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT)
        index = load<std::uint32_t>(v.data + i * v.stride);  // beyond float's 24 exact bits
      if (index >= vertexCount)
        fail(at, "index " + std::to_string(index) + " at element " + str(i) + " is out of range (" +
                     str(vertexCount) + " vertices)");
      out.push_back(index);
    }
    return out;
  }

  void appendPrimitive(const tinygltf::Mesh& mesh, int meshIndex, std::size_t p, const glm::mat4& world) {
    const tinygltf::Primitive& prim = mesh.primitives[p];
    std::string at = "/meshes/" + std::to_string(meshIndex) + "/primitives/" + str(p);
    if (prim.mode != TINYGLTF_MODE_TRIANGLES)
      fail(at + "/mode", "only triangles (mode 4) are supported, got " + std::to_string(prim.mode));
    if (prim.attributes.find("POSITION") == prim.attributes.end()) fail(at + "/attributes", "no POSITION");
    std::vector<glm::vec4> positions = attribute(prim, "POSITION", 3, false, at, 0);
    std::vector<glm::vec4> normals = attribute(prim, "NORMAL", 3, false, at, positions.size());
    std::vector<glm::vec4> tangents = attribute(prim, "TANGENT", 4, false, at, positions.size());
    std::vector<glm::vec4> uvs = attribute(prim, "TEXCOORD_0", 2, true, at, positions.size());
    std::vector<std::uint32_t> idx = indices(prim, at, positions.size());
    if (idx.size() % 3 != 0) fail(at, "triangle list of " + str(idx.size()) + " indices, not a multiple of 3");

    Mesh out;
    out.name = fs::path(mName).filename().string() + "/" +
               (mesh.name.empty() ? "mesh" + std::to_string(meshIndex) : mesh.name) + "/" + str(p);
    if (mPlacement.materialOverride >= 0) out.material = mPlacement.materialOverride;
    else if (prim.material >= 0) {
      item(mModel.materials, prim.material, "material", at + "/material");
      out.material = mMaterials[static_cast<std::size_t>(prim.material)];
    } else {
      out.material = defaultMaterial();
    }
    if (uvs.empty()) {  // a texture at one uv shows one texel's colour over the whole primitive
      const Material& m = mScene.materials.at(static_cast<std::size_t>(out.material));
      if (m.baseColourTexture >= 0 || m.metallicRoughnessTexture >= 0 || m.normalTexture >= 0 ||
          m.emissiveTexture >= 0 || m.spectralTexture)
        fail(at + "/attributes", "no TEXCOORD_0, which material '" + m.name + "' needs for its textures");
    }
    auto vertex = [&](std::uint32_t i) {
      Vertex v;
      v.position = glm::vec3(positions[i]);
      if (!normals.empty()) v.normal = glm::vec3(normals[i]);
      if (!uvs.empty()) v.uv = glm::vec2(uvs[i]);
      if (!tangents.empty()) v.tangent = tangents[i];
      return v;
    };
    if (normals.empty()) {
      // Flat normals: every triangle gets its own three vertices.
      for (std::size_t t = 0; t < idx.size(); t += 3) {
        Vertex a = vertex(idx[t]), b = vertex(idx[t + 1]), c = vertex(idx[t + 2]);
        glm::vec3 n = glm::cross(b.position - a.position, c.position - a.position);
        n = glm::length(n) > 0.0f ? glm::normalize(n) : glm::vec3(0.0f, 1.0f, 0.0f);
        for (Vertex* v : {&a, &b, &c}) {
          v->normal = n;
          out.indices.push_back(static_cast<std::uint32_t>(out.vertices.size()));
          out.vertices.push_back(*v);
        }
      }
    } else {
      for (std::uint32_t i = 0; i < positions.size(); ++i) {
        Vertex v = vertex(i);
        if (glm::length(v.normal) > 0.0f) v.normal = glm::normalize(v.normal);
        out.vertices.push_back(v);
      }
      out.indices = std::move(idx);
      computeZeroNormals(out);  // a zero NORMAL (the spec's are unit) from the faces around it
    }
    if (normals.empty() || tangents.empty()) computeTangents(out);
    transformMesh(out, mPlacement.transform * world);
    mScene.meshes.push_back(std::move(out));
  }

  const tinygltf::Model& mModel;
  std::string mName;
  const GltfPlacement& mPlacement;
  Scene& mScene;
  std::vector<int> mMaterials;                     // glTF material → Scene::materials
  std::vector<bool> mUsedMaterials;                // per glTF material: named by a primitive
  std::map<std::pair<int, bool>, int> mTextures;  // (glTF image, sRGB) → Scene::textures
  int mDefaultMaterial = -1;
  std::vector<bool> mOnPath;
  std::vector<std::string> mReachedFrom;  // per node, the pointer it was first reached from
};

}  // namespace

void appendGltf(const fs::path& file, const fs::path& root, const GltfPlacement& placement, Scene& scene) {
  Converter(loadGltfModel(file, root, scene.files), file.string(), placement, scene).run();
}

}  // namespace prism
