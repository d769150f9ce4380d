#include "app/merge_command.h"

#include <fmt/format.h>

#include "app/reference_commands.h"
#include "batch/reference_merge.h"
#include "core/atomic_file.h"
#include "core/error.h"
#include "core/file_extension.h"
#include "spectral/rgb_to_spectrum_part.h"
#include "techniques/prt/transfer_bake.h"
#include "techniques/prt/transfer_part.h"

namespace prism::app {

void runMerge(const MergeOptions& o) {
  for (const std::filesystem::path& part : o.parts) {
    requireOtherFile(o.output, part, "a part it merges");
    requireOtherFile(o.variance, part, "a part it merges");
  }
  if (!o.parts.empty() && isTablePart(o.parts.front())) {
    if (!o.variance.empty()) throw Error("--variance: parts of an upsampling table have none");
    refuseImageExtension(o.output, "-o", "upsampling table");
    requireWritable(o.output);
    RgbToSpectrumTable table = mergeTableParts(o.parts);
    table.save(o.output);
    fmt::print("merged {} parts into {} ({} table, {}³)\n", o.parts.size(), o.output.string(), table.gamut(),
               table.resolution());
    return;
  }
  if (!o.parts.empty() && prt::isTransferPart(o.parts.front())) {
    if (!o.variance.empty()) throw Error("--variance: parts of a PRT bake have none");
    refuseImageExtension(o.output, "-o", "PRT transfer");
    requireWritable(o.output);
    prt::TransferPart whole = prt::mergeTransferParts(o.parts);
    prt::writeTransferFile(o.output, whole.key, whole.samples, whole.transfer);
    fmt::print("merged {} parts into {} (PRT transfer of {} vertices, {} directions each, key {:016x})\n",
               o.parts.size(), o.output.string(), whole.vertexCount, whole.samples, whole.key);
    return;
  }
  checkReferenceOutputs(o.output, o.variance);
  requireWritable(o.output);
  if (!o.variance.empty()) requireWritable(o.variance);
  batch::MergedReference merged = batch::mergeReferenceParts(o.parts);
  writeReferenceImage(merged.image, merged.header.observer, merged.header.ev100, o.output, o.variance);
  fmt::print("merged {} parts into {} ({}x{}, {} paths per pixel)\n", o.parts.size(), o.output.string(),
             merged.header.width, merged.header.height, merged.header.samplesPerPixel);
}

}  // namespace prism::app
