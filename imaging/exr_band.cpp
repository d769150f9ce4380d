#include "imaging/exr_band.h"

#include <OpenEXR/ImfChannelList.h>
#include <OpenEXR/ImfFrameBuffer.h>
#include <OpenEXR/ImfHeader.h>
#include <OpenEXR/ImfInputFile.h>
#include <OpenEXR/ImfOutputFile.h>
#include <OpenEXR/ImfStdIO.h>
#include <OpenEXR/ImfStringAttribute.h>

#include <algorithm>
#include <cstdint>
#include <string>

#include "core/atomic_file.h"
#include "core/error.h"
#include "core/input_file.h"
#include "imaging/exr_file.h"
#include "imaging/openexr_message.h"

namespace prism::imaging {
namespace {

Imf::FrameBuffer frameBuffer(const std::vector<std::string>& channels, std::vector<std::vector<float>>& planes,
                             const Imath::Box2i& dataWindow, int width) {
  Imf::FrameBuffer frame;
  for (std::size_t c = 0; c < channels.size(); ++c) {
    frame.insert(channels[c], Imf::Slice::Make(Imf::FLOAT, planes[c].data(), dataWindow, sizeof(float),
                                               sizeof(float) * static_cast<std::size_t>(width)));
  }
  return frame;
}

}  // namespace

void writeExrBand(const std::filesystem::path& path, const ExrBand& band) {
  PRISM_CHECK(band.width > 0 && band.rowBegin >= 0 && band.rows > 0 && band.rowBegin + band.rows <= band.height);
  PRISM_CHECK(band.planes.size() == band.channels.size());
  const std::size_t values = static_cast<std::size_t>(band.width) * static_cast<std::size_t>(band.rows);
  for (const std::vector<float>& plane : band.planes) PRISM_CHECK(plane.size() == values);

  const Imath::Box2i display({0, 0}, {band.width - 1, band.height - 1});
  const Imath::Box2i data({0, band.rowBegin}, {band.width - 1, band.rowBegin + band.rows - 1});
  Imf::Header header(display, data);
  header.compression() = Imf::ZIP_COMPRESSION;
  for (const std::string& name : band.channels) header.channels().insert(name, Imf::Channel(Imf::FLOAT));
  for (const auto& [name, value] : band.attributes) header.insert(name, Imf::StringAttribute(value));
  // OpenEXR's slices take non-const pointers for reading and writing alike; writing only reads them.
  auto& planes = const_cast<std::vector<std::vector<float>>&>(band.planes);
  Imf::StdOSStream stream;
  try {
    Imf::OutputFile file(stream, header);  // its destructor writes the offset table: before str()
    file.setFrameBuffer(frameBuffer(band.channels, planes, data, band.width));
    file.writePixels(band.rows);
  } catch (const std::exception& e) {
    throw Error(path.string() + ": cannot encode EXR: " + openExrMessage(e.what()));
  }
  writeFileAtomically(path, stream.str());
}

ExrBand readExrBand(const std::filesystem::path& path, bool pixels) {
  requireInputFile(path, "an image");
  try {
    checkExrHeaderSizes(path);
    Imf::InputFile file(path.c_str());
    const Imf::Header& header = file.header();
    const Imath::Box2i display = header.displayWindow(), data = header.dataWindow();
    ExrBand band;
    const std::int64_t width = std::int64_t{display.max.x} + 1, height = std::int64_t{display.max.y} + 1;
    if (display.min.x != 0 || display.min.y != 0 || width < 1 || height < 1 || width > kMaxExrSide ||
        height > kMaxExrSide) {
      throw Error(path.string() + ": the display window is not an image of 1 to " + std::to_string(kMaxExrSide) +
                  " pixels a side at (0, 0)");
    }
    if (data.min.x != 0 || data.max.x != display.max.x || data.min.y < 0 || data.max.y < data.min.y ||
        data.max.y > display.max.y) {
      throw Error(path.string() + ": the data window is not whole rows of the display window");
    }
    band.width = static_cast<int>(width);
    band.height = static_cast<int>(height);
    band.rowBegin = data.min.y;
    band.rows = data.max.y - data.min.y + 1;
    for (auto it = header.begin(); it != header.end(); ++it) {
      if (const auto* text = dynamic_cast<const Imf::StringAttribute*>(&it.attribute()))
        band.attributes[it.name()] = text->value();
    }
    for (auto it = header.channels().begin(); it != header.channels().end(); ++it) band.channels.emplace_back(it.name());
    if (!pixels) return band;
    const std::size_t values = static_cast<std::size_t>(band.width) * static_cast<std::size_t>(band.rows);
    band.planes.assign(band.channels.size(), std::vector<float>(values));
    file.setFrameBuffer(frameBuffer(band.channels, band.planes, data, band.width));
    file.readPixels(data.min.y, data.max.y);
    return band;
  } catch (const Error&) {
    throw;
  } catch (const std::exception& e) {
    throw Error(path.string() + ": cannot read EXR: " + openExrMessage(e.what()));
  }
}

}  // namespace prism::imaging
