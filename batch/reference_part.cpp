#include "batch/reference_part.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <fstream>
#include <iterator>
#include <map>
#include <span>
#include <sstream>

#include <fmt/format.h>

#include "core/error.h"
#include "core/fnv1a.h"
#include "core/task_split.h"
#include "scene/scene.h"
#include "imaging/exr_band.h"
#include "imaging/float_image.h"
#include "spectral/observer.h"
#include "spectral/spectral_texture.h"

namespace prism::batch {
namespace {

constexpr const char* kPartKind = "reference 1";
constexpr const char* kCameraToXyz = "prism:cameraToXyz";

// A part's colour channels (its own layout, read by merge alone: a whole image stores XYZ in R, G,
// B, imaging/exr_file.h).
bool isCamera(const std::string& observerName) { return observer(observerName).isCamera; }
std::vector<std::string> colourNames(const std::string& observerName) {
  return isCamera(observerName) ? std::vector<std::string>{"R", "G", "B"} : std::vector<std::string>{"X", "Y", "Z"};
}

// Reading a part's attributes: Error "PATH: not a part of a reference render (WHY)".
class Attributes {
 public:
  Attributes(const std::filesystem::path& path, const std::map<std::string, std::string>& attributes)
      : mPath(path), mAttributes(attributes) {}
  [[noreturn]] void fail(const std::string& why) const {
    throw Error(fmt::format("{}: not a part of a reference render ({})", mPath.string(), why));
  }
  const std::string& text(const std::string& name) const {
    auto it = mAttributes.find(name);
    if (it == mAttributes.end()) fail("no " + name);
    return it->second;
  }
  template <typename T>
  T number(const std::string& name) const {
    return parse<T>(name, text(name));
  }
  // Nine finite numbers, row by row, separated by spaces.
  Eigen::Matrix3d matrix(const std::string& name) const {
    std::istringstream words(text(name));
    std::vector<std::string> values{std::istream_iterator<std::string>(words), std::istream_iterator<std::string>()};
    if (values.size() != 9) fail(fmt::format("{} holds {} numbers, not 9", name, values.size()));
    Eigen::Matrix3d m;
    for (int i = 0; i < 9; ++i) m(i / 3, i % 3) = parse<double>(name, values[static_cast<std::size_t>(i)]);
    if (!m.allFinite()) fail(name + " holds a value that is not finite");
    return m;
  }

 private:
  template <typename T>
  T parse(const std::string& name, const std::string& t) const {
    T value{};
    auto [end, ec] = std::from_chars(t.data(), t.data() + t.size(), value);
    if (!t.empty() && ec == std::errc::result_out_of_range && end == t.data() + t.size())
      fail(name + " " + excerpt(t) + " is out of its type's range");  // 1e39 for a float: a number, but no float
    if (t.empty() || ec != std::errc() || end != t.data() + t.size()) fail(name + " \"" + excerpt(t) + "\" is not a number");
    return value;
  }

  const std::filesystem::path& mPath;
  const std::map<std::string, std::string>& mAttributes;
};

ReferencePartHeader parseHeader(const std::filesystem::path& path, const imaging::ExrBand& band) {
  Attributes a(path, band.attributes);
  if (a.text("prism:part") != kPartKind) a.fail("prism:part is \"" + excerpt(a.text("prism:part")) + "\"");
  ReferencePartHeader h;
  h.scene = a.text("prism:scene");
  h.sceneHash = a.text("prism:sceneHash");
  h.settings = a.text("prism:settings");
  h.seed = a.number<std::uint32_t>("prism:seed");
  h.width = band.width;
  h.height = band.height;
  h.samplesPerPixel = a.number<int>("prism:samplesPerPixel");
  h.observer = a.text("prism:observer");
  h.ev100 = a.number<float>("prism:ev100");
  if (!(std::abs(h.ev100) <= kEv100Limit)) a.fail(fmt::format("prism:ev100 {} is beyond ±{:g}", h.ev100, kEv100Limit));
  IndexRange samples;
  try {
    samples = parseIndexRange(a.text("prism:samples"), "prism:samples");
  } catch (const Error& e) {
    a.fail(e.what());
  }
  h.region = {band.rowBegin, band.rowBegin + band.rows, samples.begin, samples.end};
  if (samples.end > h.samplesPerPixel) a.fail(fmt::format("samples {}:{} of {}", samples.begin, samples.end, h.samplesPerPixel));
  if (a.number<int>("prism:sampleCount") != samples.size()) a.fail("prism:sampleCount is not the samples' count");
  try {
    colourNames(h.observer);
  } catch (const Error& e) {
    a.fail(e.what());
  }
  if (isCamera(h.observer)) h.cameraToXyz = a.matrix(kCameraToXyz);
  return h;
}

}  // namespace

std::vector<std::pair<std::string, std::string>> ReferencePartHeader::identity() const {
  return {{"scene", sceneHash},
          {"image size", fmt::format("{}x{}", width, height)},
          {"paths per pixel", std::to_string(samplesPerPixel)},
          {"seed", std::to_string(seed)},
          {"settings", settings},
          {"observer", observer},
          {"ev100", fmt::format("{}", ev100)}};
}

std::string sceneHash(const std::filesystem::path& scene, const std::vector<std::string>& sets, const Scene& loaded) {
  std::ifstream in(scene, std::ios::binary);
  std::ostringstream bytes;
  if (!in || !(bytes << in.rdbuf())) throw Error(scene.string() + ": cannot read the scene to hash it");
  std::uint64_t hash = fnv1a(bytes.view());
  for (const std::string& set : sets) hash = fnv1a(set, fnv1a(std::string_view("\0", 1), hash));
  auto values = [&hash](std::span<const double> v) { hash = fnv1a(v.data(), v.size_bytes(), hash); };
  for (const Mesh& mesh : loaded.meshes) {
    hash = fnv1a(mesh.vertices.data(), mesh.vertices.size() * sizeof(Vertex), hash);  // 12 floats, no padding
    hash = fnv1a(mesh.indices.data(), mesh.indices.size() * sizeof(std::uint32_t), hash);
  }
  for (const Image& texture : loaded.textures) hash = fnv1a(texture.rgba.data(), texture.rgba.size(), hash);
  for (const Material& material : loaded.materials) {
    if (material.reflectance) values(material.reflectance->values());
    if (const SpectralTexture* t = material.spectralTexture.get()) {
      const std::int32_t size[2] = {t->width, t->height};
      hash = fnv1a(size, sizeof size, hash);
      values(t->wavelengthsNm);
      values(std::span(t->basis.data(), static_cast<std::size_t>(t->basis.size())));
      hash = fnv1a(t->coefficients.data(), t->coefficients.size() * sizeof(float), hash);
    }
    if (material.conductor) {
      values(material.conductor->n.values());
      values(material.conductor->k.values());
    }
    if (material.emission) values(material.emission->radiance().values());
    // What a glTF file's materials say (the file's bytes are not hashed, its meshes and images are).
    const float inputs[] = {material.baseColour.r,     material.baseColour.g,     material.baseColour.b,
                            material.metallic,         material.roughness,        material.emissiveFactor.r,
                            material.emissiveFactor.g, material.emissiveFactor.b, material.emissiveLuminance};
    const std::int32_t textures[] = {material.baseColourTexture, material.metallicRoughnessTexture,
                                     material.normalTexture, material.emissiveTexture};
    hash = fnv1a(inputs, sizeof inputs, hash);
    hash = fnv1a(textures, sizeof textures, hash);
  }
  for (const Light& light : loaded.lights) values(light.spd.values());
  for (const auto& section : loaded.techniques.all()) hash = section->hashLoadedData(hash);
  return fmt::format("{:016x}", hash);
}

std::string settingsText(const reference::ReferenceSettings& s) {
  return fmt::format("transport={} max-depth={} filter={} range={},{} strategy={}",
                     s.transport == reference::LightTransport::Global ? "global" : "direct", s.maxDepth,
                     s.filter == reference::PixelFilter::Box ? "box" : "centre", s.wavelengths.minNm,
                     s.wavelengths.maxNm, samplingStrategyName(s.wavelengths.strategy));
}

ReferencePartHeader partHeader(const std::filesystem::path& scene, const std::vector<std::string>& sets,
                               const Scene& loaded, const reference::ReferenceSettings& settings,
                               const reference::ReferenceRegion& region, float ev100) {
  return {scene.string(), sceneHash(scene, sets, loaded), settingsText(settings), settings.seed, settings.width,
          settings.height, settings.samplesPerPixel, settings.observer, ev100, region, std::nullopt};
}

void writeReferencePart(const std::filesystem::path& path, const ReferencePartHeader& h,
                        const reference::ReferenceImage& image) {
  PRISM_CHECK(image.tristimulus.width == h.width && image.tristimulus.height == h.region.rows());
  imaging::ExrBand band;
  band.width = h.width;
  band.height = h.height;
  band.rowBegin = h.region.rowBegin;
  band.rows = h.region.rows();
  band.attributes = {
      {"prism:part", kPartKind},
      {"prism:scene", h.scene},
      {"prism:sceneHash", h.sceneHash},
      {"prism:settings", h.settings},
      {"prism:seed", std::to_string(h.seed)},
      {"prism:samplesPerPixel", std::to_string(h.samplesPerPixel)},
      {"prism:observer", h.observer},
      {"prism:ev100", fmt::format("{}", h.ev100)},
      {"prism:samples", fmt::format("{}:{}", h.region.sampleBegin, h.region.sampleEnd)},
      {"prism:sampleCount", std::to_string(h.region.samples())},
      {"prism:colour", std::string(imaging::colourMeaningName(imaging::tristimulusMeaning(observer(h.observer))))},
  };
  PRISM_CHECK(h.cameraToXyz.has_value() == isCamera(h.observer));
  if (h.cameraToXyz) {
    const Eigen::Matrix3d& m = *h.cameraToXyz;
    band.attributes[kCameraToXyz] = fmt::format("{:.17g} {:.17g} {:.17g} {:.17g} {:.17g} {:.17g} {:.17g} {:.17g} {:.17g}",
                                                m(0, 0), m(0, 1), m(0, 2), m(1, 0), m(1, 1), m(1, 2), m(2, 0),
                                                m(2, 1), m(2, 2));
  }
  const std::vector<std::string> names = colourNames(h.observer);
  auto addPlanes = [&](const imaging::FloatImage& planes, const std::string& prefix) {
    for (int c = 0; c < 3; ++c) {
      band.channels.push_back(prefix + names[static_cast<std::size_t>(c)]);
      std::vector<float>& plane = band.planes.emplace_back(planes.pixelCount());
      for (std::size_t i = 0; i < plane.size(); ++i) plane[i] = planes.pixels[3 * i + static_cast<std::size_t>(c)];
    }
  };
  addPlanes(image.tristimulus, "");
  addPlanes(image.meanResidual, "residual.");
  addPlanes(image.variance, "variance.");
  imaging::writeExrBand(path, band);
}

ReferencePartHeader readReferencePartHeader(const std::filesystem::path& path) {
  return parseHeader(path, imaging::readExrBand(path, false));
}

ReferencePart readReferencePart(const std::filesystem::path& path) {
  imaging::ExrBand band = imaging::readExrBand(path, true);
  ReferencePart part{parseHeader(path, band), {}};
  const std::vector<std::string> names = colourNames(part.header.observer);
  auto image = [&](const std::string& prefix) {
    imaging::FloatImage out(band.width, band.rows, 3);
    for (int c = 0; c < 3; ++c) {
      const std::string name = prefix + names[static_cast<std::size_t>(c)];
      auto it = std::find(band.channels.begin(), band.channels.end(), name);
      if (it == band.channels.end()) Attributes(path, band.attributes).fail("no channel " + name);
      const std::vector<float>& plane = band.planes[static_cast<std::size_t>(it - band.channels.begin())];
      // What the path tracer writes: finite estimates, the image's and its variance never
      // negative (a tampered part passed -1e6 into the merged image; a NaN was blamed on the scene).
      const bool signedValues = prefix == "residual.";
      for (std::size_t i = 0; i < plane.size(); ++i) {
        if (!std::isfinite(plane[i]) || (!signedValues && plane[i] < 0.0f))
          throw Error(fmt::format("{}: channel {}, pixel ({}, {}) of the part: {} is not a {}estimate", path.string(), name,
                                  i % static_cast<std::size_t>(band.width), i / static_cast<std::size_t>(band.width),
                                  plane[i], signedValues ? "finite " : "finite, non-negative "));
        out.pixels[3 * i + static_cast<std::size_t>(c)] = plane[i];
      }
    }
    return out;
  };
  part.image = {image(""), image("variance."), image("residual.")};
  return part;
}

}  // namespace prism::batch
