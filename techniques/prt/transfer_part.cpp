#include "techniques/prt/transfer_part.h"

#include <cmath>
#include <cstring>
#include <fstream>
#include <iterator>
#include <string>

#include <fmt/format.h>

#include "core/atomic_file.h"
#include "core/binary_fields.h"
#include "core/error.h"
#include "core/fnv1a.h"

namespace prism::prt {
namespace {

constexpr char kTransferPartMagic[8] = {'P', 'R', 'I', 'S', 'M', 'P', 'T', 'P'};
constexpr std::uint32_t kTransferPartVersion = 1;
constexpr std::size_t kTransferPartHeaderBytes = 40;

}  // namespace

void saveTransferPart(const std::filesystem::path& path, const TransferPart& part) {
  PRISM_CHECK(part.vertices.begin >= 0 && part.vertices.begin < part.vertices.end &&
              part.vertices.end <= part.vertexCount &&
              part.transfer.size() == static_cast<std::size_t>(part.vertices.size()));
  std::string bytes(kTransferPartMagic, sizeof kTransferPartMagic);
  binary::append(bytes, kTransferPartVersion);
  binary::append(bytes, static_cast<std::uint32_t>(part.samples));
  binary::append(bytes, part.key);
  binary::append(bytes, static_cast<std::uint32_t>(part.vertexCount));
  binary::append(bytes, static_cast<std::uint32_t>(part.vertices.begin));
  binary::append(bytes, static_cast<std::uint32_t>(part.vertices.end));
  binary::append(bytes, std::uint32_t{25});
  for (const shared::Sh25& t : part.transfer) bytes.append(reinterpret_cast<const char*>(t.c), sizeof t.c);
  binary::append(bytes, fnv1a(bytes));
  writeFileAtomically(path, bytes);
}

TransferPart loadTransferPart(const std::filesystem::path& path) {
  const std::string where = path.string() + ": ";
  if (std::filesystem::is_directory(path)) throw Error(where + "is a folder, not a part of a PRT bake");
  std::ifstream in(path, std::ios::binary);
  if (!in) throw Error(where + "cannot open the part of a PRT bake");
  std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  if (bytes.size() < kTransferPartHeaderBytes + 8 ||
      std::memcmp(bytes.data(), kTransferPartMagic, sizeof kTransferPartMagic) != 0)
    throw Error(where + "not a part of a PRT bake (bad magic or truncated)");
  if (binary::readAt<std::uint32_t>(bytes, 8) != kTransferPartVersion)
    throw Error(where + fmt::format("PRT bake part version {} (expected {})", binary::readAt<std::uint32_t>(bytes, 8),
                                    kTransferPartVersion));
  TransferPart part;
  const std::uint32_t samples = binary::readAt<std::uint32_t>(bytes, 12);
  const std::uint32_t count = binary::readAt<std::uint32_t>(bytes, 24);
  const std::uint32_t begin = binary::readAt<std::uint32_t>(bytes, 28), end = binary::readAt<std::uint32_t>(bytes, 32);
  if (samples < 1 || samples > (1u << 20)) throw Error(where + fmt::format("{} directions per vertex, out of range 1..{}", samples, 1 << 20));
  if (count > static_cast<std::uint32_t>(INT32_MAX) || begin >= end || end > count)
    throw Error(where + fmt::format("vertices {}:{} are not of a mesh of {}", begin, end, count));
  if (binary::readAt<std::uint32_t>(bytes, 36) != 25)
    throw Error(where + fmt::format("{} SH coefficients per vertex (expected 25)", binary::readAt<std::uint32_t>(bytes, 36)));
  const std::size_t expected = kTransferPartHeaderBytes + std::size_t{end - begin} * 100 + 8;
  if (bytes.size() != expected)
    throw Error(where + fmt::format("{} part of a PRT bake ({} bytes, expected {})",
                                    bytes.size() < expected ? "truncated" : "oversized", bytes.size(), expected));
  if (binary::readAt<std::uint64_t>(bytes, expected - 8) != fnv1a(bytes.data(), expected - 8))
    throw Error(where + "damaged part of a PRT bake (checksum mismatch)");
  part.samples = static_cast<int>(samples);
  part.key = binary::readAt<std::uint64_t>(bytes, 16);
  part.vertexCount = static_cast<int>(count);
  part.vertices = {static_cast<int>(begin), static_cast<int>(end)};
  part.transfer.resize(end - begin);
  for (std::size_t v = 0; v < part.transfer.size(); ++v) {
    std::memcpy(part.transfer[v].c, bytes.data() + kTransferPartHeaderBytes + v * 100, 100);
    for (float c : part.transfer[v].c)
      if (!std::isfinite(c)) throw Error(where + fmt::format("non-finite coefficient at vertex {}", begin + v));
  }
  return part;
}

bool isTransferPart(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  char magic[sizeof kTransferPartMagic] = {};
  return in.read(magic, sizeof magic) && std::memcmp(magic, kTransferPartMagic, sizeof kTransferPartMagic) == 0;
}

TransferPart mergeTransferParts(const std::vector<std::filesystem::path>& files) {
  if (files.empty()) throw Error("merge: no parts given");
  std::vector<TransferPart> parts;
  for (const std::filesystem::path& f : files) parts.push_back(loadTransferPart(f));
  std::vector<IndexRange> ranges;
  std::vector<std::string> names;
  for (std::size_t i = 0; i < parts.size(); ++i) {
    const TransferPart& p = parts[i];
    if (p.key != parts[0].key || p.samples != parts[0].samples || p.vertexCount != parts[0].vertexCount) {
      throw Error(fmt::format("merge: {} is a part of another PRT bake (key {:016x}, {} vertices, {} directions); {}'s "
                              "is {:016x}, {}, {}",
                              files[i].string(), p.key, p.vertexCount, p.samples, files[0].string(), parts[0].key,
                              parts[0].vertexCount, parts[0].samples));
    }
    ranges.push_back(p.vertices);
    names.push_back(files[i].string());
  }
  checkCoveredOnce(ranges, names, parts[0].vertexCount, "vertices");
  TransferPart whole{parts[0].key, parts[0].samples, parts[0].vertexCount, {0, parts[0].vertexCount}, {}};
  whole.transfer.resize(static_cast<std::size_t>(whole.vertexCount));
  for (const TransferPart& p : parts)
    std::copy(p.transfer.begin(), p.transfer.end(), whole.transfer.begin() + p.vertices.begin);
  return whole;
}

}  // namespace prism::prt
