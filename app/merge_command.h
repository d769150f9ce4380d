// `prism merge PARTS… -o OUT`: the parts of a split reference render (`prism reference --tile
// I/N`, `--samples A:B`; batch/reference_merge.h) put together into the image `prism reference`
// writes without them, the same bytes when split by rows; or the parts of an upsampling table
// (`prism lut --part I/N`, told by their magic; spectral/rgb_to_spectrum_part.h) into the table
// `prism lut` writes, the same bytes; or the parts of a PRT transfer bake (`prism prt bake --part
// I/N`; techniques/prt/transfer_part.h) into the transfer file `prism prt bake` caches, the same
// bytes (written to -o: the cache's file, transfer-KEY.bin, is where the renderer finds it).
// Refuses parts of another render, gaps and overlaps in one line before writing anything; the parts are only read, so merging again
// (a resubmitted merge job) gives the same file.
#pragma once

#include <filesystem>
#include <vector>

#include "app/render_commands.h"

namespace prism::app {

struct MergeOptions {
  std::vector<std::filesystem::path> parts;
  std::filesystem::path output;    // .exr or .png, as `prism reference -o`
  std::filesystem::path variance;  // optional .exr of the per-pixel variance of the mean
  SettingsOptions display;         // a reference render's PNG: its display transform, as `prism reference`'s
};
void runMerge(const MergeOptions& options);

}  // namespace prism::app
