#include "app/merge_command.h"

#include <fmt/format.h>

#include "app/reference_commands.h"
#include "batch/reference_merge.h"
#include "core/atomic_file.h"

namespace prism::app {

void runMerge(const MergeOptions& o) {
  checkReferenceOutputs(o.output, o.variance);
  requireWritable(o.output);
  if (!o.variance.empty()) requireWritable(o.variance);
  batch::MergedReference merged = batch::mergeReferenceParts(o.parts);
  writeReferenceImage(merged.image, merged.header.observer, merged.header.ev100, o.output, o.variance);
  fmt::print("merged {} parts into {} ({}x{}, {} paths per pixel)\n", o.parts.size(), o.output.string(),
             merged.header.width, merged.header.height, merged.header.samplesPerPixel);
}

}  // namespace prism::app
