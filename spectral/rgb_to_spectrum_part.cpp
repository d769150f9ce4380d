#include "spectral/rgb_to_spectrum_part.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <fstream>
#include <iterator>

#include "core/atomic_file.h"
#include "core/error.h"
#include "spectral/table_file_bytes.h"
#include "spectral/rgb_to_spectrum_optimiser.h"

namespace prism {
namespace {

using table_bytes::append;
using table_bytes::crc;
using table_bytes::readAt;

constexpr char kPartMagic[8] = {'P', 'R', 'I', 'S', 'M', 'L', 'T', 'P'};
constexpr std::uint32_t kPartVersion = 1;
constexpr std::size_t kPartHeaderBytes = 40;
constexpr std::size_t kPartGamutBytes = 16;

// The column's (block, y, x) as the optimiser numbers them.
void columnNode(int column, int res, int& block, int& yi, int& xi) {
  block = column / (res * res);
  yi = column / res % res;
  xi = column % res;
}

}  // namespace

RgbToSpectrumPart tablePart(const RgbToSpectrumTable& table, IndexRange columns) {
  const int res = table.resolution();
  PRISM_CHECK(columns.begin >= 0 && columns.begin < columns.end && columns.end <= tableColumns(res));
  RgbToSpectrumPart part{table.gamut(), res, columns, {}};
  part.coefficients.reserve(static_cast<std::size_t>(columns.size()) * static_cast<std::size_t>(res) * 3);
  for (int column = columns.begin; column < columns.end; ++column) {
    int block, yi, xi;
    columnNode(column, res, block, yi, xi);
    for (int zi = 0; zi < res; ++zi) {
      glm::vec3 c = table.coefficients(block, zi, yi, xi);
      part.coefficients.insert(part.coefficients.end(), {c.x, c.y, c.z});
    }
  }
  return part;
}

void saveTablePart(const std::filesystem::path& path, const RgbToSpectrumPart& part) {
  PRISM_CHECK(part.gamut.size() < kPartGamutBytes);
  std::string bytes(kPartMagic, sizeof kPartMagic);
  append(bytes, kPartVersion);
  append(bytes, static_cast<std::uint32_t>(part.resolution));
  char gamut[kPartGamutBytes] = {};
  std::copy(part.gamut.begin(), part.gamut.end(), gamut);
  bytes.append(gamut, kPartGamutBytes);
  append(bytes, static_cast<std::uint32_t>(part.columns.begin));
  append(bytes, static_cast<std::uint32_t>(part.columns.end));
  bytes.append(reinterpret_cast<const char*>(part.coefficients.data()), part.coefficients.size() * sizeof(float));
  append(bytes, crc(bytes.data(), bytes.size()));
  writeFileAtomically(path, bytes);
}

RgbToSpectrumPart loadTablePart(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw Error(path.string() + ": cannot open upsampling table part");
  std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const std::string where = path.string() + ": ";
  if (bytes.size() < kPartHeaderBytes + 4 || std::memcmp(bytes.data(), kPartMagic, sizeof kPartMagic) != 0)
    throw Error(where + "not a part of an upsampling table (bad magic or truncated)");
  if (readAt<std::uint32_t>(bytes, 8) != kPartVersion)
    throw Error(where + "unsupported table part version " + std::to_string(readAt<std::uint32_t>(bytes, 8)));
  RgbToSpectrumPart part;
  const std::uint32_t res = readAt<std::uint32_t>(bytes, 12);
  if (res < 2 || res > 256) throw Error(where + "bad resolution " + std::to_string(res));
  part.resolution = static_cast<int>(res);
  part.gamut.assign(bytes.data() + 16, strnlen(bytes.data() + 16, kPartGamutBytes));
  const std::uint32_t begin = readAt<std::uint32_t>(bytes, 32), end = readAt<std::uint32_t>(bytes, 36);
  if (begin >= end || end > static_cast<std::uint32_t>(tableColumns(part.resolution)))
    throw Error(where + "columns " + std::to_string(begin) + ":" + std::to_string(end) + " are not of a " +
                std::to_string(res) + "³ table");
  part.columns = {static_cast<int>(begin), static_cast<int>(end)};
  const std::size_t floats = static_cast<std::size_t>(end - begin) * res * 3;
  const std::size_t expected = kPartHeaderBytes + 4 * floats + 4;
  if (bytes.size() != expected)
    throw Error(where + (bytes.size() < expected ? "truncated" : "oversized") + " upsampling table part (" +
                std::to_string(bytes.size()) + " bytes, expected " + std::to_string(expected) + ")");
  if (readAt<std::uint32_t>(bytes, expected - 4) != crc(bytes.data(), expected - 4))
    throw Error(where + "corrupt upsampling table part (checksum mismatch)");
  part.coefficients.resize(floats);
  std::memcpy(part.coefficients.data(), bytes.data() + kPartHeaderBytes, 4 * floats);
  // As the table's loader: merged in, a NaN was written into a table that then failed to load.
  for (float v : part.coefficients)
    if (!std::isfinite(v)) throw Error(where + "non-finite coefficient in upsampling table part");
  return part;
}

bool isTablePart(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  char magic[sizeof kPartMagic] = {};
  return in.read(magic, sizeof magic) && std::memcmp(magic, kPartMagic, sizeof kPartMagic) == 0;
}

RgbToSpectrumTable mergeTableParts(const std::vector<std::filesystem::path>& files) {
  if (files.empty()) throw Error("merge: no parts given");
  std::vector<RgbToSpectrumPart> parts;
  for (const std::filesystem::path& f : files) parts.push_back(loadTablePart(f));
  for (std::size_t i = 1; i < parts.size(); ++i) {
    if (parts[i].gamut != parts[0].gamut || parts[i].resolution != parts[0].resolution) {
      throw Error("merge: " + files[i].string() + " is a part of another table: " + parts[i].gamut + " " +
                  std::to_string(parts[i].resolution) + "³, " + files[0].string() + "'s is " + parts[0].gamut + " " +
                  std::to_string(parts[0].resolution) + "³");
    }
  }
  const int res = parts[0].resolution;
  std::vector<IndexRange> columns;
  std::vector<std::string> names;
  for (std::size_t i = 0; i < parts.size(); ++i) {
    columns.push_back(parts[i].columns);
    names.push_back(files[i].string());
  }
  checkCoveredOnce(columns, names, tableColumns(res), "columns");

  RgbToSpectrumTable table(parts[0].gamut, res);
  for (const RgbToSpectrumPart& part : parts) {
    std::size_t k = 0;
    for (int column = part.columns.begin; column < part.columns.end; ++column) {
      int block, yi, xi;
      columnNode(column, res, block, yi, xi);
      for (int zi = 0; zi < res; ++zi, k += 3) {
        table.setCoefficients(block, zi, yi, xi,
                              {part.coefficients[k], part.coefficients[k + 1], part.coefficients[k + 2]});
      }
    }
  }
  return table;
}

}  // namespace prism
