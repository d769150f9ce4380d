#include "techniques/prt/transfer_bake.h"

#include <cmath>
#include <cstring>
#include <fstream>
#include <iterator>
#include <limits>
#include <numbers>
#include <optional>
#include <span>

#include <fmt/format.h>

#include "core/atomic_file.h"
#include "core/cache_folder.h"
#include "core/error.h"
#include "core/fnv1a.h"
#include "core/parallel_for.h"
#include "rays/triangle_bvh.h"

namespace prism::prt {
namespace {

// The transfer cache's bound, the least recently used entries going first: each bake of an edited
// mesh adds an entry (10 MB at 100 000 vertices), which piled up for good. A scene whose transfers
// hold more than this bakes some again at every run.
constexpr std::size_t kMostTransfers = 256;
constexpr std::uintmax_t kMostTransferBytes = std::uintmax_t{4} << 30;

constexpr char kMagic[8] = {'P', 'R', 'I', 'S', 'M', 'P', 'R', 'T'};
constexpr std::uint32_t kVersion = 1;
constexpr std::size_t kHeaderBytes = 8 + 4 + 4 + 8 + 4 + 4;

double radicalInverseBase2(std::uint32_t i) {
  i = (i << 16u) | (i >> 16u);
  i = ((i & 0x55555555u) << 1u) | ((i & 0xAAAAAAAAu) >> 1u);
  i = ((i & 0x33333333u) << 2u) | ((i & 0xCCCCCCCCu) >> 2u);
  i = ((i & 0x0F0F0F0Fu) << 4u) | ((i & 0xF0F0F0F0u) >> 4u);
  i = ((i & 0x00FF00FFu) << 8u) | ((i & 0xFF00FF00u) >> 8u);
  return i * 2.3283064365386963e-10;
}

// An orthonormal frame about a unit normal (Duff et al. 2017, "Building an Orthonormal Basis,
// Revisited", Listing 3).
void frame(const glm::vec3& n, glm::vec3& t, glm::vec3& b) {
  float sign = std::copysign(1.0f, n.z);
  float a = -1.0f / (sign + n.z);
  float c = n.x * n.y * a;
  t = glm::vec3(1.0f + sign * n.x * n.x * a, sign * c, -sign * n.x);
  b = glm::vec3(c, sign + n.y * n.y * a, -n.y);
}

void checkMesh(const PrtMesh& mesh) {
  if (mesh.positions.empty() || mesh.indices.empty() || mesh.indices.size() % 3 != 0)
    throw Error(fmt::format("PRT bake: a mesh needs triangles ({} positions, {} indices)", mesh.positions.size(),
                            mesh.indices.size()));
  if (mesh.normals.size() != mesh.positions.size())
    throw Error(fmt::format("PRT bake: {} normals for {} positions", mesh.normals.size(), mesh.positions.size()));
  for (std::size_t i = 0; i < mesh.indices.size(); ++i)
    if (mesh.indices[i] >= mesh.positions.size())
      throw Error(fmt::format("PRT bake: index {} (at {}) out of range ({} positions)", mesh.indices[i], i,
                              mesh.positions.size()));
}

}  // namespace

std::vector<shared::Sh25> bakeTransfer(const PrtMesh& mesh, const BakeSettings& settings, const Progress& progress,
                                       unsigned threads) {
  return bakeTransfer(mesh, settings, IndexRange{0, static_cast<int>(mesh.positions.size())}, progress, threads);
}

std::vector<shared::Sh25> bakeTransfer(const PrtMesh& mesh, const BakeSettings& settings, IndexRange vertices,
                                       const Progress& progress, unsigned threads) {
  checkMesh(mesh);
  if (vertices.begin < 0 || vertices.end <= vertices.begin || static_cast<std::size_t>(vertices.end) > mesh.positions.size())
    throw Error(fmt::format("PRT bake: vertices {}:{} outside the mesh's {}", vertices.begin, vertices.end,
                            mesh.positions.size()));
  if (settings.samples < 1 || settings.samples > (1 << 20))
    throw Error(fmt::format("PRT bake: {} samples out of range 1..{}", settings.samples, 1 << 20));
  glm::vec3 lo(std::numeric_limits<float>::max()), hi(-std::numeric_limits<float>::max());
  for (const glm::vec3& p : mesh.positions) {
    lo = glm::min(lo, p);
    hi = glm::max(hi, p);
  }
  float diagonal = glm::length(hi - lo);
  // Rays leave 1e-4 of the object's size above the surface: past float rounding at the vertex,
  // well below any feature the transfer resolves.
  float offset = 1e-4f * std::max(diagonal, 1e-6f);
  float tMax = 4.0f * std::max(diagonal, 1e-6f);

  // Directions in the normal's frame: cosine-weighted from a Hammersley set.
  const int n = settings.samples;
  std::vector<glm::vec3> local(static_cast<std::size_t>(n));
  for (int i = 0; i < n; ++i) {
    double u1 = (i + 0.5) / n, u2 = radicalInverseBase2(static_cast<std::uint32_t>(i));
    double r = std::sqrt(u1), phi = 2.0 * std::numbers::pi * u2;
    local[static_cast<std::size_t>(i)] =
        glm::vec3(static_cast<float>(r * std::cos(phi)), static_cast<float>(r * std::sin(phi)),
                  static_cast<float>(std::sqrt(std::max(0.0, 1.0 - u1))));
  }

  std::optional<rays::TriangleBvh> occluder;
  if (settings.shadows) {
    const rays::TriangleMesh object{0, mesh.positions, mesh.indices};
    occluder.emplace(std::span(&object, 1));
  }
  std::vector<shared::Sh25> transfer(static_cast<std::size_t>(vertices.size()));
  parallelFor(
      transfer.size(), threads,
      [&](std::size_t i) {
        const std::size_t v = static_cast<std::size_t>(vertices.begin) + i;
        glm::vec3 normal = mesh.normals[v], t, b;
        frame(normal, t, b);
        glm::vec3 origin = mesh.positions[v] + offset * normal;
        double sum[25] = {};
        for (const glm::vec3& d : local) {
          glm::vec3 dir = glm::normalize(d.x * t + d.y * b + d.z * normal);
          if (occluder && occluder->occluded(origin, dir, 0.0f, tMax)) continue;
          shared::Sh25 y = shared::shEvaluate(dir);
          for (int k = 0; k < 25; ++k) sum[k] += y.c[k];
        }
        // Cosine-weighted pdf cos θ/π: T̃_k = (1/N) Σ V Y_k cos θ / (cos θ/π) = (π/N) Σ V Y_k.
        for (int k = 0; k < 25; ++k) transfer[i].c[k] = static_cast<float>(sum[k] * std::numbers::pi / n);
      },
      progress);
  return transfer;
}

std::uint64_t transferKey(const PrtMesh& mesh, const BakeSettings& settings) {
  std::uint64_t h = fnv1a(&kVersion, sizeof kVersion);
  h = fnv1a(mesh.positions.data(), mesh.positions.size() * sizeof(glm::vec3), h);
  h = fnv1a(mesh.normals.data(), mesh.normals.size() * sizeof(glm::vec3), h);
  h = fnv1a(mesh.indices.data(), mesh.indices.size() * sizeof(std::uint32_t), h);
  std::int32_t samples = settings.samples, shadows = settings.shadows ? 1 : 0;
  h = fnv1a(&samples, sizeof samples, h);
  return fnv1a(&shadows, sizeof shadows, h);
}

void writeTransferFile(const std::filesystem::path& path, std::uint64_t key, int samples,
                       const std::vector<shared::Sh25>& transfer) {
  std::string bytes;
  auto put = [&bytes](const void* p, std::size_t size) { bytes.append(static_cast<const char*>(p), size); };
  put(kMagic, sizeof kMagic);
  put(&kVersion, 4);
  auto samplesU = static_cast<std::uint32_t>(samples);
  put(&samplesU, 4);
  put(&key, 8);
  auto count = static_cast<std::uint32_t>(transfer.size());
  std::uint32_t coefficients = 25;
  put(&count, 4);
  put(&coefficients, 4);
  for (const shared::Sh25& t : transfer) put(t.c, sizeof t.c);
  std::uint64_t checksum = fnv1a(bytes.data(), bytes.size());
  put(&checksum, 8);
  writeFileAtomically(path, bytes);
}

std::vector<shared::Sh25> readTransferFile(const std::filesystem::path& path, std::uint64_t key) {
  const std::string where = path.string() + ": ";
  if (std::filesystem::is_directory(path)) throw Error(where + "is a folder, not a PRT transfer file");
  std::ifstream in(path, std::ios::binary);
  if (!in) throw Error(where + "cannot open PRT transfer file");
  std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  auto read = [&bytes](std::size_t at, auto& value) { std::memcpy(&value, bytes.data() + at, sizeof value); };
  if (bytes.size() < kHeaderBytes + 8) throw Error(where + fmt::format("truncated PRT transfer file ({} bytes)", bytes.size()));
  if (std::memcmp(bytes.data(), kMagic, sizeof kMagic) != 0) throw Error(where + "not a PRT transfer file (bad magic)");
  std::uint32_t version = 0, count = 0, coefficients = 0;
  std::uint64_t fileKey = 0, checksum = 0;
  read(8, version);
  read(16, fileKey);
  read(24, count);
  read(28, coefficients);
  if (version != kVersion) throw Error(where + fmt::format("PRT transfer file version {} (expected {})", version, kVersion));
  if (coefficients != 25) throw Error(where + fmt::format("{} SH coefficients per vertex (expected 25)", coefficients));
  std::size_t expected = kHeaderBytes + std::size_t{count} * 25 * 4 + 8;
  if (bytes.size() != expected)
    throw Error(where + fmt::format("{} bytes, expected {} for {} vertices", bytes.size(), expected, count));
  read(expected - 8, checksum);
  if (checksum != fnv1a(bytes.data(), expected - 8)) throw Error(where + "damaged PRT transfer file (checksum mismatch)");
  if (fileKey != key) throw Error(where + "PRT transfer file for another mesh or settings (key mismatch)");
  std::vector<shared::Sh25> transfer(count);
  for (std::uint32_t v = 0; v < count; ++v) {
    std::memcpy(transfer[v].c, bytes.data() + kHeaderBytes + std::size_t{v} * 100, 100);
    for (float c : transfer[v].c)
      if (!std::isfinite(c)) throw Error(where + fmt::format("non-finite coefficient at vertex {}", v));
  }
  return transfer;
}

std::filesystem::path transferCacheFile(const std::filesystem::path& cacheDir, std::uint64_t key) {
  return cacheDir / "prt" / fmt::format("transfer-{:016x}.bin", key);
}

CachedTransfer cachedTransfer(const PrtMesh& mesh, const BakeSettings& settings, const std::filesystem::path& cacheDir,
                              const Progress& progress, const std::function<void(const std::string&)>& note,
                              unsigned threads) {
  std::uint64_t key = transferKey(mesh, settings);
  CachedTransfer result;
  result.file = transferCacheFile(cacheDir, key);
  requireNoFolderAtEntry(result.file, "a PRT transfer");  // said so once, not "rebuilding" and then refused
  if (std::filesystem::exists(result.file)) {
    try {
      result.transfer = readTransferFile(result.file, key);
      if (result.transfer.size() == mesh.positions.size()) {
        result.fromCache = true;
        touchCacheEntry(result.file);
        return result;
      }
      if (note) note(result.file.string() + ": vertex count differs from the mesh; rebuilding");
    } catch (const Error& e) {
      if (note) note(std::string(e.what()) + "; rebuilding");
    }
  }
  requireWritable(result.file);  // before the bake, not after
  result.transfer = bakeTransfer(mesh, settings, progress, threads);
  writeTransferFile(result.file, key, settings.samples, result.transfer);
  pruneCacheFolder(result.file.parent_path(), "transfer-", ".bin", kMostTransfers, kMostTransferBytes);
  return result;
}

}  // namespace prism::prt
