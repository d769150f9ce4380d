#include "spectral/rgb_to_spectrum_table.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <fstream>
#include <iterator>

#include "shared_cpp.h"
#include "core/atomic_file.h"
#include "core/error.h"
#include "spectral/colour_space.h"
#include "spectral/table_file_bytes.h"

namespace prism::shared {
#include "upsampling.glsl"
}

namespace prism {
namespace {

using table_bytes::append;
using table_bytes::crc;
using table_bytes::readAt;

constexpr char kMagic[8] = {'P', 'R', 'I', 'S', 'M', 'L', 'U', 'T'};
constexpr std::uint32_t kVersion = 1;
constexpr std::uint32_t kNodeLayout = 1;
constexpr std::size_t kHeaderBytes = 40;
constexpr std::size_t kGamutBytes = 16;

std::size_t payloadFloats(int res) {
  auto n = static_cast<std::size_t>(res);
  return n + 3 * n * n * n * 3;
}

}  // namespace

RgbToSpectrumTable::RgbToSpectrumTable(std::string gamut, int resolution)
    : mGamut(std::move(gamut)), mResolution(resolution) {
  if (resolution < 2 || resolution > 256)
    throw Error("upsampling table resolution must be within 2–256, got " + std::to_string(resolution));
  if (mGamut.empty() || mGamut.size() >= kGamutBytes)
    throw Error("upsampling table gamut name must have 1–15 characters: '" + mGamut + "'");
  mData.assign(3 * static_cast<std::size_t>(resolution) * static_cast<std::size_t>(resolution) *
                   static_cast<std::size_t>(resolution) * 3,
               0.0f);
}

float RgbToSpectrumTable::brightnessNode(int k) const {
  return shared::lutScaleOfNode(static_cast<float>(k) / static_cast<float>(mResolution - 1));
}

std::size_t RgbToSpectrumTable::index(int block, int zi, int yi, int xi) const {
  PRISM_CHECK(block >= 0 && block < 3 && zi >= 0 && zi < mResolution && yi >= 0 && yi < mResolution && xi >= 0 &&
              xi < mResolution);  // out of range read past the table
  auto n = static_cast<std::size_t>(mResolution);
  return (((static_cast<std::size_t>(block) * n + static_cast<std::size_t>(zi)) * n +
           static_cast<std::size_t>(yi)) * n + static_cast<std::size_t>(xi)) * 3;
}

glm::vec3 RgbToSpectrumTable::coefficients(int block, int zi, int yi, int xi) const {
  std::size_t i = index(block, zi, yi, xi);
  return {mData[i], mData[i + 1], mData[i + 2]};
}

void RgbToSpectrumTable::setCoefficients(int block, int zi, int yi, int xi, const glm::vec3& c) {
  std::size_t i = index(block, zi, yi, xi);
  mData[i] = c.x;
  mData[i + 1] = c.y;
  mData[i + 2] = c.z;
}

glm::vec3 RgbToSpectrumTable::nodeRgb(int block, int zi, int yi, int xi) const {
  float last = static_cast<float>(mResolution - 1);
  float z = brightnessNode(zi);
  glm::vec3 rgb;
  rgb[block] = z;
  rgb[(block + 1) % 3] = shared::lutRatioOfNode(static_cast<float>(xi) / last) * z;
  rgb[(block + 2) % 3] = shared::lutRatioOfNode(static_cast<float>(yi) / last) * z;
  return rgb;
}

glm::vec3 RgbToSpectrumTable::lookup(const glm::vec3& rgb) const {
  shared::LutCell c = shared::lutCell(shared::lutPosition(rgb), mResolution);
  auto at = [&](int dx, int dy, int dz) { return coefficients(c.block, c.zi + dz, c.yi + dy, c.xi + dx); };
  return shared::lutTrilinear(at(0, 0, 0), at(1, 0, 0), at(0, 1, 0), at(1, 1, 0), at(0, 0, 1),
                              at(1, 0, 1), at(0, 1, 1), at(1, 1, 1), c.weight);
}

glm::vec3 RgbToSpectrumTable::lookupFiltered(const glm::vec3& rgb, int weightBits) const {
  // What GL_LINEAR on a res × res × 3res texture does at the shared texture coordinate:
  // texel = coord·size − ½, blend floor and floor + 1.
  glm::vec3 uvw = shared::lutFilteredCoordinate(shared::lutPosition(rgb), mResolution);
  float n = static_cast<float>(mResolution);
  glm::vec3 texel(uvw.x * n - 0.5f, uvw.y * n - 0.5f, uvw.z * 3.0f * n - 0.5f);
  glm::ivec3 lo(glm::floor(texel));
  glm::vec3 w = texel - glm::vec3(lo);
  if (weightBits > 0) {
    float steps = std::ldexp(1.0f, weightBits);
    w = glm::floor(w * steps + 0.5f) / steps;
  }
  auto at = [&](int dx, int dy, int dz) {
    int x = std::clamp(lo.x + dx, 0, mResolution - 1);
    int y = std::clamp(lo.y + dy, 0, mResolution - 1);
    int z = std::clamp(lo.z + dz, 0, 3 * mResolution - 1);
    return coefficients(z / mResolution, z % mResolution, y, x);
  };
  return shared::lutTrilinear(at(0, 0, 0), at(1, 0, 0), at(0, 1, 0), at(1, 1, 0), at(0, 0, 1),
                              at(1, 0, 1), at(0, 1, 1), at(1, 1, 1), w);
}

void RgbToSpectrumTable::save(const std::filesystem::path& path) const {
  std::string bytes;
  bytes.reserve(kHeaderBytes + 4 * payloadFloats(mResolution) + 4);
  bytes.append(kMagic, sizeof kMagic);
  append(bytes, kVersion);
  append(bytes, static_cast<std::uint32_t>(mResolution));
  char gamut[kGamutBytes] = {};
  std::copy(mGamut.begin(), mGamut.end(), gamut);
  bytes.append(gamut, kGamutBytes);
  append(bytes, kNodeLayout);
  append(bytes, mInputsHash);
  for (int k = 0; k < mResolution; ++k) append(bytes, brightnessNode(k));
  bytes.append(reinterpret_cast<const char*>(mData.data()), mData.size() * sizeof(float));
  append(bytes, crc(bytes.data(), bytes.size()));
  writeFileAtomically(path, bytes);
}

RgbToSpectrumTable RgbToSpectrumTable::load(const std::filesystem::path& path) {
  // A folder opens as a stream whose first read throws std::ios_base::failure, not an Error.
  if (std::filesystem::is_directory(path)) throw Error(path.string() + ": is a folder, not an upsampling table");
  std::ifstream in(path, std::ios::binary);
  if (!in) throw Error(path.string() + ": cannot open upsampling table");
  std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const std::string where = path.string() + ": ";
  if (bytes.size() < kHeaderBytes + 4)
    throw Error(where + "truncated upsampling table (" + std::to_string(bytes.size()) + " bytes)");
  if (std::memcmp(bytes.data(), kMagic, sizeof kMagic) != 0)
    throw Error(where + "not a Prism upsampling table (bad magic)");
  if (auto version = readAt<std::uint32_t>(bytes, 8); version != kVersion)
    throw Error(where + "unsupported upsampling table version " + std::to_string(version) +
                " (expected " + std::to_string(kVersion) + ")");
  auto res = readAt<std::uint32_t>(bytes, 12);
  if (res < 2 || res > 256) throw Error(where + "bad resolution " + std::to_string(res));
  std::string gamut(bytes.data() + 16, kGamutBytes);
  gamut.resize(std::strlen(gamut.c_str()));
  if (auto axis = readAt<std::uint32_t>(bytes, 32); axis != kNodeLayout)
    throw Error(where + "unknown node layout " + std::to_string(axis));
  std::size_t expected = kHeaderBytes + 4 * payloadFloats(static_cast<int>(res)) + 4;
  if (bytes.size() != expected)
    throw Error(where + (bytes.size() < expected ? "truncated" : "oversized") +
                " upsampling table: " + std::to_string(bytes.size()) + " bytes, expected " +
                std::to_string(expected) + " for resolution " + std::to_string(res));
  if (readAt<std::uint32_t>(bytes, expected - 4) != crc(bytes.data(), expected - 4))
    throw Error(where + "corrupt upsampling table (checksum mismatch)");
  RgbToSpectrumTable table(gamut, static_cast<int>(res));
  table.mInputsHash = readAt<std::uint32_t>(bytes, 36);
  for (int k = 0; k < table.mResolution; ++k)
    if (readAt<float>(bytes, kHeaderBytes + 4 * static_cast<std::size_t>(k)) != table.brightnessNode(k))
      throw Error(where + "brightness node " + std::to_string(k) +
                  " differs from this build's node layout (table from another build?)");
  std::memcpy(table.mData.data(), bytes.data() + kHeaderBytes + 4 * res, table.mData.size() * sizeof(float));
  for (float v : table.mData)
    if (!std::isfinite(v)) throw Error(where + "non-finite coefficient in upsampling table");
  return table;
}

void requireTableForColourSpace(const RgbToSpectrumTable& table, std::string_view colourSpaceName,
                                std::string_view where) {
  if (table.gamut() != colourSpace(colourSpaceName).name)
    throw Error(std::string(where) + ": the upsampling table is for " + table.gamut() + ", the scene is in " +
                std::string(colourSpaceName));
}

}  // namespace prism
