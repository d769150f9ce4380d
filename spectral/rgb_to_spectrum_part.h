// A part of a Jakob–Hanika table built by columns across the tasks of a cluster (`prism lut
// --part I/N`, one Slurm array task each; rgb_to_spectrum_optimiser.h): the coefficients of the
// columns [begin, end), which `prism merge` puts together into the table one process builds,
// byte for byte (columns are fitted independently of each other).
//
// File format (little-endian, version 1):
//   offset  size          field
//   0       8             magic "PRISMLTP"
//   8       4  u32        version (1)
//   12      4  u32        resolution n
//   16      16 char[16]   gamut name, zero-padded
//   32      4  u32        first column
//   36      4  u32        end column (exclusive); column = block·n² + y·n + x
//   40      12n per column, in order: for z = 0…n−1, the coefficients c0 c1 c2 (f32)
//   end−4   4  u32        CRC-32 (zlib) of every byte before it
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "core/task_split.h"
#include "spectral/rgb_to_spectrum_table.h"

namespace prism {

struct RgbToSpectrumPart {
  std::string gamut;
  int resolution = 0;
  IndexRange columns;
  std::vector<float> coefficients;  // columns.size() × resolution × 3, in the file's order
};

// The columns of `table` (built with those columns at least).
RgbToSpectrumPart tablePart(const RgbToSpectrumTable& table, IndexRange columns);

// Atomically (a task that dies leaves no part).
void saveTablePart(const std::filesystem::path& path, const RgbToSpectrumPart& part);

// Error naming the file and the field when it is not a whole, sound part.
RgbToSpectrumPart loadTablePart(const std::filesystem::path& path);

// Whether the file starts with a part's magic (what `prism merge` dispatches on).
bool isTablePart(const std::filesystem::path& path);

// The table of parts of one gamut and resolution that hold every column exactly once; Error
// "merge: …" naming the other table, or the first columns missing or in two parts.
RgbToSpectrumTable mergeTableParts(const std::vector<std::filesystem::path>& files);

}  // namespace prism
