#include "imaging/exr_file.h"

#include <Imath/half.h>
#include <OpenEXR/ImfChannelList.h>
#include <OpenEXR/ImfChromaticities.h>
#include <OpenEXR/ImfFrameBuffer.h>
#include <OpenEXR/ImfHeader.h>
#include <OpenEXR/ImfInputFile.h>
#include <OpenEXR/ImfOutputFile.h>
#include <OpenEXR/ImfStandardAttributes.h>
#include <OpenEXR/ImfStdIO.h>
#include <OpenEXR/ImfFloatAttribute.h>
#include <OpenEXR/ImfMatrixAttribute.h>
#include <OpenEXR/ImfStringAttribute.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <fstream>
#include <optional>
#include <string>
#include <string_view>
#include <tuple>
#include <utility>
#include <vector>

#include <fmt/format.h>

#include "core/atomic_file.h"
#include "core/error.h"
#include "core/input_file.h"
#include "imaging/openexr_message.h"

namespace prism::imaging {
namespace {

constexpr const char* kColourAttribute = "prism:colour";
// The largest finite half (IEEE 754 binary16).
constexpr float kHalfMax = 65504.0f;

// OpenEXR's convention for CIE XYZ in an RGB file (OpenEXR, "Technical Introduction", §
// "Chromaticities"): primaries at the corners of the xy triangle, equal-energy white.
Imf::Chromaticities xyzChromaticities() {
  return Imf::Chromaticities({1.0f, 0.0f}, {0.0f, 1.0f}, {0.0f, 0.0f}, {1.0f / 3.0f, 1.0f / 3.0f});
}

bool near(const Imath::V2f& a, const Imath::V2f& b) {
  // Chromaticities are stored as float; 1e-4 allows for files that wrote 4-digit values.
  return std::abs(a.x - b.x) < 1e-4f && std::abs(a.y - b.y) < 1e-4f;
}

bool sameChromaticities(const Imf::Chromaticities& a, const Imf::Chromaticities& b) {
  return near(a.red, b.red) && near(a.green, b.green) && near(a.blue, b.blue) && near(a.white, b.white);
}

// R, G, B (+ A) whatever they hold, "Y" alone: CIE XYZ too, OpenEXR's convention ("Technical
// Introduction", "CIE XYZ Color": X, Y, Z in R, G, B with xyzChromaticities), which other tools
// read as colour. Prism wrote channels X, Y, Z beside those chromaticities, which apply to R, G, B:
// a tool took the lone Y for luminance and dropped X and Z. (Such files are still read.)
std::vector<std::string> channelNamesToWrite(const FloatImage& image) {
  if (image.channels == 1) return {"Y"};
  std::vector<std::string> names{"R", "G", "B"};
  if (image.channels == 4) names.push_back("A");
  return names;
}

// The bytes of a value of each fixed-size attribute type OpenEXR 3.1 knows (its file layout,
// "Attribute types"), which it reads whatever the attribute's size says.
std::optional<std::int64_t> fixedExrAttributeSize(std::string_view type) {
  static constexpr std::pair<std::string_view, std::int64_t> kSizes[] = {
      {"box2i", 16}, {"box2f", 16}, {"chromaticities", 32}, {"compression", 1}, {"deepImageState", 1},
      {"double", 8}, {"envmap", 1}, {"float", 4}, {"int", 4}, {"keycode", 28}, {"lineOrder", 1},
      {"m33f", 36}, {"m33d", 72}, {"m44f", 64}, {"m44d", 128}, {"rational", 8}, {"tiledesc", 9},
      {"timecode", 8}, {"v2i", 8}, {"v2f", 8}, {"v2d", 16}, {"v3i", 12}, {"v3f", 12}, {"v3d", 24}};
  for (const auto& [name, bytes] : kSizes)
    if (name == type) return bytes;
  return std::nullopt;
}

// The camera a camera-RGB image records: both attributes or neither, a finite matrix, and only on
// camera RGB (elsewhere the channels are not the camera's).
std::optional<ExrCamera> readCamera(const std::filesystem::path& path, const Imf::Header& header,
                                    ColourMeaning colour) {
  const auto* name = header.findTypedAttribute<Imf::StringAttribute>(kCameraAttribute);
  const auto* matrix = header.findTypedAttribute<Imf::M33dAttribute>(kCameraToXyzAttribute);
  for (const auto& [attribute, type, found] : {std::tuple{kCameraAttribute, "string", name != nullptr},
                                               std::tuple{kCameraToXyzAttribute, "m33d", matrix != nullptr}}) {
    const Imf::Header::ConstIterator any = header.find(attribute);
    if (!found && any != header.end())  // a part's string matrix in a whole image, say
      throw Error(fmt::format("{}: {} is of type {}, not {}", path.string(), attribute, any.attribute().typeName(), type));
  }
  if (!name && !matrix) return std::nullopt;
  if (!name || !matrix)
    throw Error(fmt::format("{}: {} without {} (a string and an m33d, written together)", path.string(),
                            name ? kCameraAttribute : kCameraToXyzAttribute,
                            name ? kCameraToXyzAttribute : kCameraAttribute));
  if (colour != ColourMeaning::CameraRgb)
    throw Error(fmt::format("{}: {} on {} values, which are no camera's", path.string(), kCameraAttribute,
                            colourMeaningName(colour)));
  ExrCamera camera{name->value(), Eigen::Matrix3d()};
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c) camera.toXyz(r, c) = matrix->value()[r][c];
  if (!camera.toXyz.allFinite())
    throw Error(fmt::format("{}: {}: holds a value that is not finite", path.string(), kCameraToXyzAttribute));
  return camera;
}

}  // namespace

void writeExr(const std::filesystem::path& path, const FloatImage& image, const ExrWriteOptions& options) {
  PRISM_CHECK(image.channels == 1 || image.channels == 3 || image.channels == 4);
  PRISM_CHECK(image.pixels.size() == image.pixelCount() * static_cast<std::size_t>(image.channels));
  if (image.width <= 0 || image.height <= 0)
    throw Error(path.string() + ": cannot write an empty image (" + std::to_string(image.width) + " × " +
                std::to_string(image.height) + ") as EXR");
  bool half = options.precision == ExrPrecision::Half;
  if (half) {
    auto outside = std::find_if(image.pixels.begin(), image.pixels.end(),
                                [](float v) { return std::isfinite(v) && std::abs(v) > kHalfMax; });
    if (outside != image.pixels.end())
      throw Error(path.string() + ": value " + std::to_string(*outside) +
                  " is beyond half precision's 65504; write as float or scale the image");
  }

  Imf::Header header(image.width, image.height);
  header.compression() = Imf::ZIP_COMPRESSION;
  Imf::PixelType fileType = half ? Imf::HALF : Imf::FLOAT;
  std::vector<std::string> names = channelNamesToWrite(image);
  for (const std::string& name : names) header.channels().insert(name, Imf::Channel(fileType));
  if (image.channels != 1) {
    header.insert(kColourAttribute, Imf::StringAttribute(std::string(colourMeaningName(options.colour))));
    // Imf::Chromaticities() is Rec. 709 primaries with D65, i.e. linear sRGB.
    if (options.colour == ColourMeaning::LinearSrgb) Imf::addChromaticities(header, Imf::Chromaticities());
    // CIE 1964's X₁₀Y₁₀Z₁₀ too: the nearest a tool that knows only 1931's xy can take them for.
    if (options.colour == ColourMeaning::Xyz || options.colour == ColourMeaning::Xyz1964)
      Imf::addChromaticities(header, xyzChromaticities());
  }
  if (options.displayWhite) {
    header.insert(kDisplayWhiteAttribute, Imf::FloatAttribute(static_cast<float>(*options.displayWhite)));
  }
  if (options.camera) {
    PRISM_CHECK(options.colour == ColourMeaning::CameraRgb && options.camera->toXyz.allFinite());
    header.insert(kCameraAttribute, Imf::StringAttribute(options.camera->name));
    Imath::M33d m;
    for (int r = 0; r < 3; ++r)
      for (int c = 0; c < 3; ++c) m[r][c] = options.camera->toXyz(r, c);
    header.insert(kCameraToXyzAttribute, Imf::M33dAttribute(m));
  }

  // OutputFile does not convert pixel types (InputFile does), so half gets its own copy,
  // rounded to nearest by Imath::half.
  std::vector<Imath::half> halves;
  if (half) halves.assign(image.pixels.begin(), image.pixels.end());
  const std::size_t sampleSize = half ? sizeof(Imath::half) : sizeof(float);
  const std::size_t xStride = sampleSize * static_cast<std::size_t>(image.channels);
  const std::size_t yStride = xStride * static_cast<std::size_t>(image.width);
  Imf::FrameBuffer frame;
  for (std::size_t c = 0; c < names.size(); ++c) {
    const void* first = half ? static_cast<const void*>(halves.data() + c) : image.pixels.data() + c;
    frame.insert(names[c], Imf::Slice::Make(fileType, first, header.dataWindow(), xStride, yStride));
  }
  Imf::StdOSStream stream;
  try {
    // The file's destructor writes the line offset table, so it must end before str().
    Imf::OutputFile file(stream, header);
    file.setFrameBuffer(frame);
    file.writePixels(image.height);
  } catch (const std::exception& e) {
    throw Error(path.string() + ": cannot encode EXR: " + openExrMessage(e.what()));
  }
  writeFileAtomically(path, stream.str());
}

ExrWriteOptions tristimulusExr(const Observer& observer, double displayWhite, const Eigen::Matrix3d& cameraToXyz) {
  ExrWriteOptions options{.colour = tristimulusMeaning(observer), .displayWhite = displayWhite};
  if (observer.isCamera) options.camera = ExrCamera{observer.name, cameraToXyz};
  return options;
}

void checkExrHeaderSizes(const std::filesystem::path& path) {
  // The first header's attributes: name, type, size, value; an empty name ends it.
  // The header only, read as it is walked: an EXR's pixels may be gigabytes that OpenEXR reads next.
  std::ifstream in(path, std::ios::binary | std::ios::ate);
  if (!in) return;  // OpenEXR reports it
  const std::uint64_t fileSize = static_cast<std::uint64_t>(in.tellg());
  in.seekg(0);
  unsigned char head[8] = {};
  const unsigned char magic[4] = {0x76, 0x2f, 0x31, 0x01};
  if (!in.read(reinterpret_cast<char*>(head), 8) || !std::equal(magic, magic + 4, head)) return;  // OpenEXR says what it is not
  // Names and type names are at most 31 bytes, or 255 with the long-names flag (OpenEXR's file
  // layout, "Version Field"); OpenEXR reads past a longer one as if it had ended there.
  const std::uint32_t version = head[4] | head[5] << 8 | head[6] << 16 | static_cast<std::uint32_t>(head[7]) << 24;
  // Bits 11 and 12: deep data, several parts (whose other headers this walk would not check).
  if ((version & 0x1800u) != 0)
    throw Error(path.string() + ": a multi-part or deep EXR file; Prism reads single-part scan-line and tiled images");
  const std::size_t longest = (version & 0x400u) != 0 ? 255 : 31;
  auto readString = [&](const char* what) {
    std::string text;
    char c = 0;
    while (in.get(c) && c != 0 && text.size() <= longest) text.push_back(c);
    if (!in || c != 0)
      throw Error(path.string() + ": malformed EXR header: an attribute's " + what + " does not end");
    return text;
  };
  while (true) {
    std::string name = readString("name");
    if (name.empty()) return;
    const std::string type = readString("type");
    unsigned char size4[4] = {};
    if (!in.read(reinterpret_cast<char*>(size4), 4))
      throw Error(path.string() + ": malformed EXR header: attribute '" + excerpt(name) + "' has no size");
    const std::int64_t size = static_cast<std::int32_t>(size4[0] | size4[1] << 8 | size4[2] << 16 |
                                                        static_cast<std::uint32_t>(size4[3]) << 24);
    const std::uint64_t left = fileSize - static_cast<std::uint64_t>(in.tellg());
    if (size < 0 || static_cast<std::uint64_t>(size) > left) {
      throw Error(path.string() + ": malformed EXR header: attribute '" + excerpt(name) + "' claims " +
                  std::to_string(size) + " bytes, " + std::to_string(left) + " are left");
    }
    // OpenEXR reads the values of the types it knows by their contents, not by their size: a
    // value that ends elsewhere than its size says would make it read the rest of the header from
    // another place than this walk (where a string may claim gigabytes). Fixed-size types take
    // their size; a channel list is entries of a name and 16 bytes up to an empty name; a preview
    // is its width and height and 4 bytes a pixel; a string vector is strings of a 4-byte length
    // each, read while the size is not yet reached; a float vector is whole floats.
    const std::streamoff start = in.tellg();
    std::int64_t contents = size;
    if (const std::optional<std::int64_t> fixed = fixedExrAttributeSize(type)) {
      contents = *fixed;
    } else if (type == "floatvector") {
      contents = size - size % 4;
    } else if (type == "stringvector") {
      contents = 0;
      while (contents < size && in) {
        unsigned char length4[4] = {};
        in.read(reinterpret_cast<char*>(length4), 4);
        const std::int64_t length = static_cast<std::int32_t>(length4[0] | length4[1] << 8 | length4[2] << 16 |
                                                              static_cast<std::uint32_t>(length4[3]) << 24);
        if (length < 0) break;
        contents += 4 + length;
        in.seekg(length, std::ios::cur);
      }
      if (in && contents < size) contents = -1;  // a negative length
    } else if (type == "chlist") {
      while (!readString("channel name").empty()) in.seekg(16, std::ios::cur);
      contents = in.tellg() - start;
    } else if (type == "preview") {
      unsigned char sides[8] = {};
      if (size < 8 || !in.read(reinterpret_cast<char*>(sides), 8))
        throw Error(path.string() + ": malformed EXR header: preview '" + excerpt(name) + "' has no size");
      auto side = [&](int at) {
        return static_cast<std::uint64_t>(sides[at] | sides[at + 1] << 8 | sides[at + 2] << 16 |
                                          static_cast<std::uint32_t>(sides[at + 3]) << 24);
      };
      const std::uint64_t width = side(0), height = side(4);
      const bool fits = height == 0 || width <= static_cast<std::uint64_t>(size) / height;  // no overflow
      contents = fits ? static_cast<std::int64_t>(8 + 4 * width * height) : -1;
    }
    if (!in || contents != size) {
      throw Error(path.string() + ": malformed EXR header: attribute '" + excerpt(name) + "' (" + excerpt(type) +
                  ") holds " + (in ? std::to_string(contents) : std::string("more")) + " bytes, its size says " +
                  std::to_string(size));
    }
    // OpenEXR allocates its line and tile buffers by these as it opens the file: checked first.
    if ((name == "dataWindow" && type == "box2i") || (name == "tiles" && type == "tiledesc")) {
      in.seekg(start);
      std::int32_t v[4] = {};
      in.read(reinterpret_cast<char*>(v), name == "tiles" ? 8 : 16);
      const bool tiles = name == "tiles";
      const std::int64_t wide = tiles ? static_cast<std::uint32_t>(v[0]) : std::int64_t{v[2]} - v[0] + 1;
      const std::int64_t high = tiles ? static_cast<std::uint32_t>(v[1]) : std::int64_t{v[3]} - v[1] + 1;
      if (!in || wide < 1 || high < 1 || wide > kMaxExrSide || high > kMaxExrSide) {
        throw Error(path.string() + ": " + (tiles ? "tiles" : "an image") + " of " + std::to_string(wide) + " × " +
                    std::to_string(high) + " pixels; Prism reads 1 to " + std::to_string(kMaxExrSide) +
                    " on each side");
      }
    }
    in.seekg(start + size);
  }
}

ExrImage readExr(const std::filesystem::path& path) {
  requireInputFile(path, "an image");
  try {
    checkExrHeaderSizes(path);
    Imf::InputFile file(path.c_str());
    const Imf::Header& header = file.header();
    const Imf::ChannelList& channels = header.channels();
    auto has = [&](const char* name) { return channels.findChannel(name) != nullptr; };

    std::vector<std::string> names;
    if (has("R") && has("G") && has("B")) {
      names = {"R", "G", "B"};
    } else if (has("X") && has("Y") && has("Z")) {
      names = {"X", "Y", "Z"};
    } else if (has("Y") && !has("RY") && !has("BY")) {
      names = {"Y"};
    } else {
      // The first few names and a count: a spectral texture has 81, a message of 1 000 characters.
      constexpr int kNamed = 4;
      std::string found;
      int count = 0;
      for (auto it = channels.begin(); it != channels.end(); ++it, ++count)
        if (count < kNamed) found += (found.empty() ? "" : ", ") + excerpt(it.name(), 24);
      if (count > kNamed) found += " and " + std::to_string(count - kNamed) + " more";
      throw Error(path.string() + ": no R, G, B or X, Y, Z or lone Y channels (it has: " +
                  (found.empty() ? "none" : found) + ")");
    }
    if (names.size() == 3 && has("A")) names.push_back("A");

    const Imath::Box2i dataWindow = header.dataWindow();
    const std::int64_t wide = std::int64_t{dataWindow.max.x} - dataWindow.min.x + 1;
    const std::int64_t high = std::int64_t{dataWindow.max.y} - dataWindow.min.y + 1;
    PRISM_CHECK(wide >= 1 && high >= 1 && wide <= kMaxExrSide && high <= kMaxExrSide);  // checkExrHeaderSizes
    const int width = static_cast<int>(wide);
    const int height = static_cast<int>(high);
    ExrImage out;
    out.wholeImage = dataWindow == header.displayWindow();
    out.image = FloatImage(width, height, static_cast<int>(names.size()));
    const std::size_t xStride = sizeof(float) * names.size();
    const std::size_t yStride = xStride * static_cast<std::size_t>(width);
    Imf::FrameBuffer frame;
    for (std::size_t c = 0; c < names.size(); ++c)
      frame.insert(names[c],
                   Imf::Slice::Make(Imf::FLOAT, out.image.pixels.data() + c, dataWindow, xStride, yStride));
    file.setFrameBuffer(frame);
    file.readPixels(dataWindow.min.y, dataWindow.max.y);

    if (const auto* colour = header.findTypedAttribute<Imf::StringAttribute>(kColourAttribute)) {
      try {
        out.colour = colourMeaningFromName(colour->value());
      } catch (const Error& e) {
        throw Error(path.string() + ": " + kColourAttribute + ": " + e.what());
      }
    } else if (Imf::hasChromaticities(header)) {
      const Imf::Chromaticities& c = Imf::chromaticities(header);
      out.colour = sameChromaticities(c, Imf::Chromaticities()) ? ColourMeaning::LinearSrgb
                   : sameChromaticities(c, xyzChromaticities()) ? ColourMeaning::Xyz
                                                                : ColourMeaning::OtherRgb;
    } else {
      out.colour = names[0] == "X" ? ColourMeaning::Xyz : ColourMeaning::LinearSrgb;
    }
    if (const auto* part = header.findTypedAttribute<Imf::StringAttribute>(kPartAttribute)) out.part = part->value();
    if (const auto* white = header.findTypedAttribute<Imf::FloatAttribute>(kDisplayWhiteAttribute)) {
      if (!(white->value() > 0.0f) || !std::isfinite(white->value())) {
        throw Error(path.string() + ": " + kDisplayWhiteAttribute + ": expected a positive number, got " +
                    std::to_string(white->value()));
      }
      out.displayWhite = white->value();
    }
    // A part records its camera's matrix as text (ReferencePartHeader reads it); read here as a
    // whole image's, it was refused for its type before any word that the file is a part.
    if (!out.part) out.camera = readCamera(path, header, out.colour);
    return out;
  } catch (const Error&) {
    throw;
  } catch (const std::exception& e) {
    throw Error(path.string() + ": cannot read EXR: " + openExrMessage(e.what()));
  }
}

}  // namespace prism::imaging
