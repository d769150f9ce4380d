// The light-transport half of spectral PRT: per vertex, the transfer T(ω) = V(ω)·max(n·ω, 0)
// projected on 25 real SH (Sloan et al. 2002, Eq. 8, "shadowed diffuse transfer"; achromatic, as
// Schwenk et al. use it). V is found with Embree rays against the object itself.
//
// Directions: a fixed 2-D Hammersley set mapped to the cosine-weighted hemisphere about each
// vertex normal (Malley's method), so T̃_k = (π/N) Σ_i V(ω_i) Y_k(ω_i): deterministic, every
// vertex its own work item (core/parallel_for.h), results independent of the thread count.
//
// Cache: one file per (mesh, settings), named by a 64-bit FNV-1a hash of the positions, normals,
// indices, sample count and format version, written atomically with an FNV-1a checksum of its
// bytes. A damaged or foreign file is reported in one line and rebuilt.
#pragma once

#include <cstdint>
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "core/task_split.h"
#include "techniques/prt/prt_shared.h"

namespace prism::prt {

struct PrtMesh {
  std::vector<glm::vec3> positions;
  std::vector<glm::vec3> normals;       // unit, one per position
  std::vector<std::uint32_t> indices;   // three per triangle
};

struct BakeSettings {
  int samples = 1024;     // directions per vertex, 1..1<<20
  bool shadows = true;    // false: V = 1 (the unshadowed transfer, for tests and comparisons)
};

using Progress = std::function<void(std::size_t done, std::size_t total)>;

// Error when the mesh is inconsistent (index out of range, normals count) or Embree fails.
std::vector<shared::Sh25> bakeTransfer(const PrtMesh& mesh, const BakeSettings& settings,
                                       const Progress& progress = {}, unsigned threads = 0);
// The transfer of the vertices [vertices.begin, vertices.end) only, occluded by the whole mesh:
// the same values, bit for bit, as those vertices of bakeTransfer (a task's share of a split
// bake, transfer_part.h). Error when the range is empty or past the mesh.
std::vector<shared::Sh25> bakeTransfer(const PrtMesh& mesh, const BakeSettings& settings, IndexRange vertices,
                                       const Progress& progress = {}, unsigned threads = 0);

std::uint64_t transferKey(const PrtMesh& mesh, const BakeSettings& settings);

// The file format: "PRISMPRT", u32 version, u32 samples, u64 key, u32 vertices, u32 25, then
// vertices × 25 float32 (little-endian, as the machine), then u64 FNV-1a of all bytes before it.
void writeTransferFile(const std::filesystem::path& path, std::uint64_t key, int samples,
                       const std::vector<shared::Sh25>& transfer);
// Error "PATH: why" when the file is missing, damaged, or for another key.
std::vector<shared::Sh25> readTransferFile(const std::filesystem::path& path, std::uint64_t key);

struct CachedTransfer {
  std::vector<shared::Sh25> transfer;
  std::filesystem::path file;
  bool fromCache = false;
};
// Reads cacheDir/prt/transfer-KEY.bin, or bakes and writes it; `note` receives one line when a
// cached file could not be used ("…; rebuilding").
CachedTransfer cachedTransfer(const PrtMesh& mesh, const BakeSettings& settings,
                              const std::filesystem::path& cacheDir, const Progress& progress = {},
                              const std::function<void(const std::string&)>& note = {}, unsigned threads = 0);
// Where cachedTransfer keeps the transfer of `key`: cacheDir/prt/transfer-KEY.bin (16 hex digits).
std::filesystem::path transferCacheFile(const std::filesystem::path& cacheDir, std::uint64_t key);

}  // namespace prism::prt
