// A part of a PRT transfer bake split across the tasks of a cluster (`prism prt bake --part I/N`,
// one Slurm array task each): the transfer of the vertices [begin, end) of a mesh, which `prism
// merge` puts together into the transfer file one process bakes (transfer_bake.h), byte for byte
// (each vertex is baked on its own, occluded by the whole mesh).
//
// File format (little-endian, version 1):
//   offset  size              field
//   0       8                 magic "PRISMPTP"
//   8       4  u32            version (1)
//   12      4  u32            directions per vertex (the bake's samples)
//   16      8  u64            the whole bake's key (transferKey: mesh and settings)
//   24      4  u32            the mesh's vertex count
//   28      4  u32            first vertex
//   32      4  u32            end vertex (exclusive)
//   36      4  u32            coefficients per vertex (25)
//   40      100 per vertex    25 × f32, SH order
//   end−8   8  u64            FNV-1a of every byte before it
#pragma once

#include <cstdint>
#include <filesystem>
#include <vector>

#include "core/task_split.h"
#include "techniques/prt/prt_shared.h"

namespace prism::prt {

struct TransferPart {
  std::uint64_t key = 0;
  int samples = 0;
  int vertexCount = 0;     // the whole mesh's
  IndexRange vertices;     // this part's
  std::vector<shared::Sh25> transfer;  // vertices.size() of them
};

// Atomically (a task that dies leaves no part).
void saveTransferPart(const std::filesystem::path& path, const TransferPart& part);

// Error "PATH: why" when it is not a whole, sound part.
TransferPart loadTransferPart(const std::filesystem::path& path);

// Whether the file starts with a part's magic (what `prism merge` dispatches on).
bool isTransferPart(const std::filesystem::path& path);

// The whole bake from parts of one key that hold every vertex exactly once (vertexCount of them,
// with `key` and `samples` for writeTransferFile); Error "merge: …" naming the part of another
// bake, or the first vertices missing or in two parts.
TransferPart mergeTransferParts(const std::vector<std::filesystem::path>& files);

}  // namespace prism::prt
