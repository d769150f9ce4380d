#include "scene/gltf_input.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>

#include "core/error.h"
#include "core/file_extension.h"
#include "imaging/png_file.h"
#include "core/json_schema.h"

namespace prism {

namespace {

namespace fs = std::filesystem;
using schema::Node;

// ---------------------------------------------------------------------------------------------
// Images

enum class ImageKind { Png, Jpeg, Exr, Hdr, Other };

ImageKind sniffImage(std::span<const std::uint8_t> b) {
  auto starts = [&](std::initializer_list<unsigned> magic) {
    if (b.size() < magic.size()) return false;
    std::size_t i = 0;
    for (unsigned m : magic)
      if (b[i++] != m) return false;
    return true;
  };
  if (starts({0x89, 'P', 'N', 'G', 0x0D, 0x0A, 0x1A, 0x0A})) return ImageKind::Png;
  if (starts({0xFF, 0xD8, 0xFF})) return ImageKind::Jpeg;
  if (starts({0x76, 0x2F, 0x31, 0x01})) return ImageKind::Exr;
  if (starts({'#', '?'})) return ImageKind::Hdr;  // "#?RADIANCE", "#?RGBE"
  return ImageKind::Other;
}

// Empty when PNG or JPEG, else why not.
std::string unsupportedImage(std::span<const std::uint8_t> bytes) {
  switch (sniffImage(bytes)) {
    case ImageKind::Png:
    case ImageKind::Jpeg: return {};
    case ImageKind::Exr: return "OpenEXR images are not supported (only PNG and JPEG)";
    case ImageKind::Hdr: return "Radiance HDR images are not supported (only PNG and JPEG)";
    case ImageKind::Other: break;
  }
  return "not a PNG or JPEG image (only PNG and JPEG are supported)";
}

// A PNG's or JPEG's size from its header, before it is decoded (imaging/png_file.h).
void checkSizeBeforeDecoding(std::span<const std::uint8_t> bytes, const std::string& name = "") {
  const ImageKind kind = sniffImage(bytes);
  if (kind == ImageKind::Png) imaging::checkPngBeforeDecoding(name.empty() ? "the PNG" : name, bytes);
  if (kind == ImageKind::Jpeg) imaging::checkJpegBeforeDecoding(name.empty() ? "the JPEG" : name, bytes);
}

// After stb failed on a PNG or JPEG: which, and why in words.
std::string undecodable(std::span<const std::uint8_t> bytes) {
  return std::string("cannot decode the ") + (sniffImage(bytes) == ImageKind::Jpeg ? "JPEG" : "PNG") + ": " +
         imaging::stbDecodeFailure();
}

std::string oneLine(std::string text) {
  while (!text.empty() && (text.back() == '\n' || text.back() == '\r')) text.pop_back();
  for (char& c : text)
    if (c == '\n' || c == '\r') c = ';';
  // tinygltf quotes what it failed on whole, e.g. a data: URI of megabytes.
  return excerpt(text, 160);
}

// tinygltf's decoded RGBA (8 or 16 bits per channel) as Prism's 8-bit RGBA.

// ---------------------------------------------------------------------------------------------
// tinygltf's file system, confined

struct Guard {
  fs::path root;
  std::string refused;     // a path the callbacks refused (outside root)
  int imageIndex = -1;     // an image the loader refused, and why
  std::string imageError;
  std::vector<fs::path> read;  // the files read, in order
};

bool guardedFileExists(const std::string& path, void* user) {
  auto* guard = static_cast<Guard*>(user);
  if (!schema::isInside(guard->root, path)) {
    guard->refused = path;
    return false;
  }
  std::error_code ec;
  return fs::is_regular_file(path, ec);
}

// No expansion of "~" or environment variables: a path means what it says.
std::string identityPath(const std::string& path, void*) { return path; }

bool guardedReadFile(std::vector<unsigned char>* out, std::string* err, const std::string& path,
                     void* user) {
  auto* guard = static_cast<Guard*>(user);
  if (!schema::isInside(guard->root, path)) {
    guard->refused = path;
    if (err) *err += "refused to read " + path + ", outside " + guard->root.string();
    return false;
  }
  try {
    *out = schema::readBinaryFile(path);
    guard->read.emplace_back(path);
  } catch (const Error& e) {
    if (err) *err += e.what();
    return false;
  }
  return true;
}

bool refuseWrite(std::string* err, const std::string& path, const std::vector<unsigned char>&, void*) {
  if (err) *err += "refused to write " + path;
  return false;
}

bool guardedImageLoader(tinygltf::Image* image, const int index, std::string* err,
                        std::string* warn, int width, int height, const unsigned char* bytes,
                        int size, void* user) {
  auto* guard = static_cast<Guard*>(user);
  const std::span<const std::uint8_t> file(bytes, static_cast<std::size_t>(std::max(size, 0)));
  std::string why = unsupportedImage(file);
  if (why.empty()) {
    try {  // as decodeImage does: a 16385-wide PNG was decoded, then refused by glTexStorage2D
      checkSizeBeforeDecoding(file);
    } catch (const Error& e) {
      why = e.what();
    }
  }
  if (!why.empty()) {
    guard->imageIndex = index;
    guard->imageError = why;
    if (err) *err += why;
    return false;
  }
  if (tinygltf::LoadImageData(image, index, err, warn, width, height, bytes, size, nullptr)) return true;
  guard->imageIndex = index;
  guard->imageError = undecodable(file);
  return false;
}

// ---------------------------------------------------------------------------------------------
// Checks on the glTF's JSON before tinygltf reads anything

// tinygltf's own URI decoding (dlib::urldecode: %XX escapes, and '+' as a space), so that the
// path checked is the path it opens.
std::string decodeUri(const std::string& uri) {
  auto hex = [](char c) -> unsigned {
    if (c >= '0' && c <= '9') return static_cast<unsigned>(c - '0');
    if (c >= 'a' && c <= 'f') return static_cast<unsigned>(c - 'a' + 10);
    if (c >= 'A' && c <= 'F') return static_cast<unsigned>(c - 'A' + 10);
    return 0;
  };
  std::string out;
  for (std::size_t i = 0; i < uri.size(); ++i) {
    if (uri[i] == '+') {
      out += ' ';
    } else if (uri[i] == '%' && uri.size() > i + 2) {
      out += static_cast<char>((hex(uri[i + 1]) << 4) | hex(uri[i + 2]));
      i += 2;
    } else {
      out += uri[i];
    }
  }
  return out;
}

// Empty, or what is wrong with the URI's %-escapes (RFC 3986 §2.1: '%' and two hex digits): a
// raw '%' ("100%.png") decoded with the next two characters as hex, here a NUL, and the file
// searched was "100"; and a %00, a NUL in a path.
std::string badEscape(const std::string& uri) {
  for (std::size_t i = 0; i < uri.size(); ++i) {
    if (uri[i] != '%') continue;
    if (i + 2 >= uri.size() || !std::isxdigit(static_cast<unsigned char>(uri[i + 1])) ||
        !std::isxdigit(static_cast<unsigned char>(uri[i + 2])))
      return "a '%' not followed by two hex digits (a URI writes '%' as %25)";
    if (uri[i + 1] == '0' && uri[i + 2] == '0') return "%00, a NUL character, in a path";
    i += 2;
  }
  return "";
}

// RFC 3986 §3.1: scheme = ALPHA *( ALPHA / DIGIT / "+" / "-" / "." ) followed by ':'.
bool hasScheme(const std::string& uri) {
  std::size_t colon = uri.find(':');
  if (colon == std::string::npos || colon == 0 || !std::isalpha(static_cast<unsigned char>(uri[0])))
    return false;
  for (std::size_t i = 1; i < colon; ++i) {
    char c = uri[i];
    if (!std::isalnum(static_cast<unsigned char>(c)) && c != '+' && c != '-' && c != '.') return false;
  }
  return true;
}

// glTF's ids and sizes (a glTFid, byteOffset, count, …) are whole numbers ≥ 0 (glTF 2.0 §5):
// tinygltf took "indices": -1 for none, drawing the mesh as a triangle soup, and a byteOffset of
// −4 for 0; and it dropped one of another type without a word ("material": "0" drew glTF's
// default material, "mesh": "0" nothing). Extras and extensions are free.
void checkIdsAndSizes(const Node& node) {
  static constexpr std::string_view kIds[] = {"indices",    "material",   "bufferView", "buffer",  "byteOffset",
                                              "byteLength", "byteStride", "count",      "source",  "sampler",
                                              "index",      "texCoord",   "mesh",       "camera",  "skin",
                                              "scene",      "nodes",      "children"};
  auto requireId = [](const Node& n) {
    const double v = n.json().is_number() ? n.json().get<double>() : -1.0;
    if (!(v >= 0.0 && v == std::floor(v))) n.fail("expected a whole number ≥ 0, got " + schema::describe(n.json()));
  };
  if (!node.json().is_object()) return;
  for (const std::string& key : node.keys()) {
    if (key == "extras" || key == "extensions") continue;
    const Node child = node.child(key);
    const nlohmann::json& value = child.json();
    const bool ids = std::find(std::begin(kIds), std::end(kIds), key) != std::end(kIds);
    if (value.is_number()) {
      if (ids) requireId(child);
    } else if (value.is_array()) {
      for (std::size_t i = 0; i < value.size(); ++i) {
        if (value[i].is_number()) {
          if (ids) requireId(child.element(i));
        } else if (ids && !value[i].is_object()) {  // objects: the top level's "nodes"
          child.element(i).fail("expected a whole number ≥ 0, got " + schema::describe(value[i]));
        } else {
          checkIdsAndSizes(child.element(i));
        }
      }
    } else if (key == "attributes" && value.is_object()) {
      for (const std::string& attribute : child.keys()) requireId(child.child(attribute));
    } else if (ids) {
      child.fail("expected a whole number ≥ 0, got " + schema::describe(value));
    } else {
      checkIdsAndSizes(child);
    }
  }
}

// The materials' and nodes' keys, their types and their arrays' lengths (glTF 2.0 §5.19, §5.25):
// tinygltf dropped a value of the wrong type, or a misspelt key, without a word — the material fell
// back to glTF's default white metal ("baseColorFactor": "red" or three numbers, a misspelt
// "baseColourFactor", "metallicFactor": "0" rendered as metal), a node kept no transform
// ("translation": "0,0,0") — and drew a node with both a matrix and translation, rotation or scale,
// which glTF forbids, by its matrix alone.
void checkMaterialsAndNodes(const Node& top) {
  auto textureInfo = [](const Node& n, std::string_view factor) {
    std::vector<std::string_view> keys{"index", "texCoord", "extensions", "extras"};
    if (!factor.empty()) keys.push_back(factor);
    n.expectObject(keys);
    n.child("index");  // required
    if (!factor.empty() && n.has(factor)) n.child(factor).number();
  };
  if (auto materials = top.optionalChild("materials")) {
    for (std::size_t i = 0; i < materials->arraySize(); ++i) {
      const Node m = materials->element(i);
      m.expectObject({"name", "extensions", "extras", "pbrMetallicRoughness", "normalTexture", "occlusionTexture",
                      "emissiveTexture", "emissiveFactor", "alphaMode", "alphaCutoff", "doubleSided"});
      if (auto pbr = m.optionalChild("pbrMetallicRoughness")) {
        pbr->expectObject({"baseColorFactor", "baseColorTexture", "metallicFactor", "roughnessFactor",
                           "metallicRoughnessTexture", "extensions", "extras"});
        if (pbr->has("baseColorFactor")) pbr->child("baseColorFactor").numbers(4);
        for (const char* factor : {"metallicFactor", "roughnessFactor"})
          if (pbr->has(factor)) pbr->child(factor).number();
        for (const char* texture : {"baseColorTexture", "metallicRoughnessTexture"})
          if (pbr->has(texture)) textureInfo(pbr->child(texture), "");
      }
      if (m.has("normalTexture")) textureInfo(m.child("normalTexture"), "scale");
      if (m.has("occlusionTexture")) textureInfo(m.child("occlusionTexture"), "strength");
      if (m.has("emissiveTexture")) textureInfo(m.child("emissiveTexture"), "");
      if (m.has("emissiveFactor")) m.child("emissiveFactor").numbers(3);
      if (auto ext = m.optionalChild("extensions")) {
        if (auto strength = ext->optionalChild("KHR_materials_emissive_strength")) {
          strength->expectObject({"emissiveStrength", "extensions", "extras"});
          if (strength->has("emissiveStrength")) strength->child("emissiveStrength").number(schema::Range::atLeast(0.0));
        }
      }
      if (m.has("alphaMode")) {
        const Node mode = m.child("alphaMode");
        const std::string name = mode.string();
        if (name != "OPAQUE" && name != "MASK" && name != "BLEND")
          mode.fail("expected OPAQUE, MASK or BLEND, got " + schema::describe(mode.json()));
      }
      if (m.has("alphaCutoff")) m.child("alphaCutoff").number();
      if (m.has("doubleSided")) m.child("doubleSided").boolean();
    }
  }
  if (auto nodes = top.optionalChild("nodes")) {
    for (std::size_t i = 0; i < nodes->arraySize(); ++i) {
      const Node n = nodes->element(i);
      n.expectObject({"camera", "children", "skin", "matrix", "mesh", "rotation", "scale", "translation", "weights",
                      "name", "extensions", "extras"});
      if (n.has("matrix")) n.child("matrix").numbers(16);
      if (n.has("translation")) n.child("translation").numbers(3);
      if (n.has("rotation")) n.child("rotation").numbers(4);
      if (n.has("scale")) n.child("scale").numbers(3);
      if (n.has("matrix") && (n.has("translation") || n.has("rotation") || n.has("scale")))
        n.child("matrix").fail("a node has a matrix or translation, rotation and scale, not both (glTF 2.0 §5.25)");
    }
  }
}

// A buffer's byteLength equal to what its base64 data: URI decodes to, as tinygltf requires:
// its own refusal quoted the whole URI ("Failed to decode 'uri' : data:…"). Counted as tinygltf
// decodes: the base64 characters up to the first '=' or other character, padding optional.
void requireDataUriHoldsByteLength(const Node& buffer, const std::string& uri) {
  auto length = buffer.optionalChild("byteLength");
  const std::size_t comma = uri.find(',');
  if (!length || !length->json().is_number_unsigned() || comma == std::string::npos) return;
  std::size_t characters = 0;
  for (std::size_t i = comma + 1; i < uri.size(); ++i, ++characters) {
    const unsigned char c = static_cast<unsigned char>(uri[i]);
    if (!std::isalnum(c) && c != '+' && c != '/') break;
  }
  const std::size_t rest = characters % 4;
  const std::size_t holds = characters / 4 * 3 + (rest > 1 ? rest - 1 : 0);
  const auto needs = length->json().get<std::uint64_t>();
  if (needs != holds)
    length->fail(std::to_string(needs) + " bytes, but the buffer's data: URI holds " + std::to_string(holds) +
                 " (the loader takes them equal)");
}

// A buffer file's size equal to its byteLength, as tinygltf requires: its own refusal named neither
// the glTF nor the buffer ("File size mismatch : cube.bin, requestedBytes 99999, but got 840").
void requireFileHoldsByteLength(const Node& buffer, const fs::path& file) {
  auto length = buffer.optionalChild("byteLength");
  std::error_code ec;
  const std::uintmax_t holds = fs::file_size(file, ec);
  if (!length || !length->json().is_number_unsigned() || ec) return;
  const auto needs = length->json().get<std::uint64_t>();
  if (needs != holds)
    length->fail(std::to_string(needs) + " bytes, but " + file.filename().string() + " holds " + std::to_string(holds) +
                 " (the loader takes them equal)");
}

void checkUris(const Node& top, const fs::path& root, const fs::path& base) {
  for (const char* section : {"buffers", "images"}) {
    auto list = top.optionalChild(section);
    if (!list) continue;
    for (std::size_t i = 0; i < list->arraySize(); ++i) {
      Node item = list->element(i);
      if (!item.json().is_object()) item.fail("expected an object, got " + schema::describe(item.json()));
      auto uriNode = item.optionalChild("uri");
      if (!uriNode) continue;
      if (!uriNode->json().is_string())
        uriNode->fail("expected a string, got " + schema::describe(uriNode->json()));
      std::string uri = uriNode->json().get<std::string>();
      if (uri.rfind("data:", 0) == 0) {
        if (!tinygltf::IsDataURI(uri))
          uriNode->fail("unsupported data URI (base64 data of type application/octet-stream, "
                        "application/gltf-buffer, image/png or image/jpeg expected)");
        if (std::string_view(section) == "buffers") requireDataUriHoldsByteLength(item, uri);
        continue;
      }
      if (hasScheme(uri))
        uriNode->fail("'" + uri + "': only relative paths and data: URIs are allowed");
      if (const std::string bad = badEscape(uri); !bad.empty()) uriNode->fail("'" + uri + "': " + bad);
      fs::path path;
      try {
        path = schema::confinedFile(root, base, decodeUri(uri));
      } catch (const Error& e) {
        uriNode->fail(e.what());
      }
      if (std::string_view(section) == "buffers") requireFileHoldsByteLength(item, path);
    }
  }
  if (auto required = top.optionalChild("extensionsRequired")) {
    for (std::size_t i = 0; i < required->arraySize(); ++i) {
      Node e = required->element(i);
      if (e.json() == "KHR_materials_emissive_strength") continue;  // read (gltf_loader.cpp)
      e.fail("the file requires extension " + schema::describe(e.json()) + ", which Prism does not support");
    }
  }
}

// The JSON chunk of a binary glTF (glTF 2.0 §4.4: 12-byte header, then chunks of length,
// type, data; the first chunk is JSON).
std::string_view glbJson(const std::vector<unsigned char>& bytes, const std::string& name) {
  auto u32 = [&](std::size_t at) {
    std::uint32_t v;
    std::memcpy(&v, bytes.data() + at, 4);
    return v;
  };
  if (bytes.size() < 20) throw Error(name + ": truncated binary glTF (" + std::to_string(bytes.size()) + " bytes)");
  if (u32(4) != 2) throw Error(name + ": binary glTF version " + std::to_string(u32(4)) + ", expected 2");
  // A cut file: tinygltf said only "Invalid glTF binary." (bytes past the header's length it
  // ignores, and so does Prism).
  if (u32(8) > bytes.size())
    throw Error(name + ": truncated: its header says " + std::to_string(u32(8)) + " bytes, the file has " +
                std::to_string(bytes.size()));
  std::uint32_t length = u32(12);
  if (u32(16) != 0x4E4F534Au || 20 + static_cast<std::size_t>(length) > bytes.size())
    throw Error(name + ": binary glTF without a valid JSON chunk");
  return {reinterpret_cast<const char*>(bytes.data()) + 20, length};
}

}  // namespace

Image toImage(const tinygltf::Image& src, bool srgb, std::string source) {
  if (src.width < 1 || src.height < 1 || src.component != 4 || (src.bits != 8 && src.bits != 16))
    throw Error("image was not decoded to 8- or 16-bit RGBA");
  Image image;
  image.width = src.width;
  image.height = src.height;
  image.srgb = srgb;
  image.source = std::move(source);
  std::size_t count = static_cast<std::size_t>(src.width) * static_cast<std::size_t>(src.height) * 4;
  if (src.image.size() != count * static_cast<std::size_t>(src.bits / 8))
    throw Error("decoded image has the wrong size");
  if (src.bits == 8) {
    image.rgba = src.image;
  } else {
    image.rgba.resize(count);
    for (std::size_t i = 0; i < count; ++i) {
      std::uint16_t v;
      std::memcpy(&v, &src.image[2 * i], 2);  // stb returns native-endian shorts
      image.rgba[i] = static_cast<std::uint8_t>((static_cast<unsigned>(v) * 255u + 32767u) / 65535u);
    }
  }
  return image;
}

Image decodeImage(std::span<const std::uint8_t> bytes, bool srgb, std::string source) {
  if (std::string why = unsupportedImage(bytes); !why.empty()) throw Error(why);
  if (bytes.size() > static_cast<std::size_t>(std::numeric_limits<int>::max())) throw Error("image file too large");
  checkSizeBeforeDecoding(bytes, source);
  tinygltf::Image decoded;
  std::string err, warn;
  if (!tinygltf::LoadImageData(&decoded, 0, &err, &warn, 0, 0, bytes.data(), static_cast<int>(bytes.size()), nullptr))
    throw Error(undecodable(bytes));
  return toImage(decoded, srgb, std::move(source));
}

tinygltf::Model loadGltfModel(const fs::path& file, const fs::path& root, std::vector<fs::path>& filesRead) {
  const std::string name = file.string();
  std::vector<unsigned char> bytes = schema::readBinaryFile(file);
  bool binary = bytes.size() >= 4 && std::memcmp(bytes.data(), "glTF", 4) == 0;
  if (!binary && lowercaseExtension(file) == ".glb")  // read as JSON, it was "malformed JSON"
    throw Error(name + ": not a binary glTF (it does not start with \"glTF\")");
  // glTF 2.0 §3.2 (JSON without a byte-order mark; tinygltf refuses one): said as such, not as
  // "not a glTF".
  if (!binary && bytes.size() >= 3 && bytes[0] == 0xEF && bytes[1] == 0xBB && bytes[2] == 0xBF)
    throw Error(name + ": starts with a UTF-8 byte-order mark, which glTF's JSON must not have (save it without one)");
  // Neither JSON's object nor a binary glTF: an image or another file named in its place.
  const auto first = std::find_if(bytes.begin(), bytes.end(), [](unsigned char c) { return !std::isspace(c); });
  if (!binary && (first == bytes.end() || *first != '{'))
    throw Error(name + ": not a glTF (a .gltf is a JSON object, a .glb starts with \"glTF\")");
  std::string_view text = binary ? glbJson(bytes, name)
                                 : std::string_view(reinterpret_cast<const char*>(bytes.data()), bytes.size());
  if (bytes.size() > std::numeric_limits<unsigned>::max()) throw Error(name + ": file too large");

  // Our own reading of the JSON first: every URI checked before anything is read, with the
  // place of the offending one.
  schema::Document document{name, {}};
  nlohmann::json json = schema::parseJson(text, name);
  Node top(json, "", document);
  if (!json.is_object()) top.fail("expected an object, got " + schema::describe(json));
  const Node version = top.child("asset").child("version");
  if (!version.string().starts_with("2.")) version.fail("glTF " + excerpt(version.string()) + ": Prism reads glTF 2.x");
  fs::path base = file.parent_path().empty() ? fs::path(".") : file.parent_path();
  checkUris(top, root, base);
  checkIdsAndSizes(top);
  checkMaterialsAndNodes(top);

  Guard guard{root, {}, -1, {}, {}};
  tinygltf::TinyGLTF loader;
  loader.SetFsCallbacks({&guardedFileExists, &identityPath, &guardedReadFile, &refuseWrite, &guard});
  loader.SetImageLoader(&guardedImageLoader, &guard);
  tinygltf::Model model;
  std::string err, warn;
  bool ok = binary ? loader.LoadBinaryFromMemory(&model, &err, &warn, bytes.data(),
                                                 static_cast<unsigned>(bytes.size()), base.string())
                   : loader.LoadASCIIFromString(&model, &err, &warn, text.data(),
                                                static_cast<unsigned>(text.size()), base.string());
  if (guard.imageIndex >= 0)
    throw Error(name + ": /images/" + std::to_string(guard.imageIndex) + ": " + guard.imageError);
  if (!ok) {
    if (!guard.refused.empty())
      throw Error(name + ": refused to read " + guard.refused + " (outside " + root.string() + ")");
    throw Error(name + ": " + oneLine(err.empty() ? "tinygltf could not load the file" : err));
  }
  filesRead.push_back(file);
  filesRead.insert(filesRead.end(), guard.read.begin(), guard.read.end());
  return model;
}

}  // namespace prism
