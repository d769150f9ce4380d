#include "app/merge_command.h"

#include <fmt/format.h>

#include <algorithm>
#include <filesystem>
#include <map>
#include <string>
#include <string_view>

#include "app/reference_commands.h"
#include "batch/reference_merge.h"
#include "core/atomic_file.h"
#include "core/error.h"
#include "core/file_extension.h"
#include "spectral/rgb_to_spectrum_part.h"
#include "techniques/prt/transfer_bake.h"
#include "techniques/prt/transfer_part.h"

namespace prism::app {
namespace {

// Parts of a table or a bake make no image: a display option given is refused, not ignored.
void refuseDisplay(const SettingsOptions& display, const char* parts) {
  if (!display.values.empty())
    throw Error(fmt::format("--{}: parts of {} make no image to display", display.values.front().first, parts));
}

// transfer-KEY.bin, KEY 16 lower-case hex digits: the name of a PRT bake in the cache
// (prt::transferCacheFile; another case is another file to the renderer, and merge says so).
bool isTransferCacheName(const std::string& name) {
  constexpr std::string_view prefix = "transfer-", suffix = ".bin";
  if (name.size() != prefix.size() + 16 + suffix.size() || !name.starts_with(prefix) || !name.ends_with(suffix))
    return false;
  return std::all_of(name.begin() + prefix.size(), name.end() - suffix.size(),
                     [](char c) { return (c >= '0' && c <= '9') || (c >= 'a' && c <= 'f'); });
}

}  // namespace

void runMerge(const MergeOptions& o) {
  for (const std::filesystem::path& part : o.parts) {
    // Missing before anything: the first part's kind picks what is merged and what -o must be.
    if (!std::filesystem::exists(part)) throw Error(part.string() + ": cannot open: no such file");
    requireOtherFile(o.output, part, "a part it merges");
    requireOtherFile(o.variance, part, "a part it merges");
  }
  // One file given twice, by the same name or another, was said to hold the same rows "in both
  // PART and PART".
  std::map<std::filesystem::path, const std::filesystem::path*> seen;
  for (const std::filesystem::path& part : o.parts) {
    std::error_code ec;
    const std::filesystem::path canonical = std::filesystem::canonical(part, ec);
    if (ec) continue;  // read, and refused, below
    if (auto [it, added] = seen.try_emplace(canonical, &part); !added)
      throw Error(*it->second == part ? fmt::format("merge: {} is given twice", part.string())
                                      : fmt::format("merge: {} and {} are the same file", it->second->string(), part.string()));
  }
  if (!o.parts.empty() && isTablePart(o.parts.front())) {
    if (!o.variance.empty()) throw Error("--variance: parts of an upsampling table have none");
    refuseDisplay(o.display, "an upsampling table");
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
    refuseDisplay(o.display, "a PRT bake");
    refuseImageExtension(o.output, "-o", "PRT transfer");
    requireWritable(o.output);
    prt::TransferPart whole = prt::mergeTransferParts(o.parts);
    // The renderer finds a bake by its name alone: one named for another key (another sample
    // count, say) was read, refused and baked again without a word.
    const std::string cacheName = prt::transferCacheFile({}, whole.key).filename().string();
    if (const std::string name = o.output.filename().string(); name != cacheName && isTransferCacheName(name))
      throw Error(fmt::format("{}: named for another bake; these parts are the bake of key {:016x}, which the renderer "
                              "reads as {}",
                              o.output.string(), whole.key, cacheName));
    prt::writeTransferFile(o.output, whole.key, whole.samples, whole.transfer);
    fmt::print("merged {} parts into {} (PRT transfer of {} vertices, {} directions each, key {:016x})\n",
               o.parts.size(), o.output.string(), whole.vertexCount, whole.samples, whole.key);
    if (o.output.filename() != cacheName)
      fmt::print("the renderer reads it as {} in its cache's prt folder (PRISM_CACHE_DIR)\n", cacheName);
    return;
  }
  // Neither a table's part nor a bake's: a reference render's (an EXR), merged into an image. A
  // first part and an output that are no images mean another kind was meant: the part is named.
  if (const std::string extension = lowercaseExtension(o.output);
      !o.parts.empty() && lowercaseExtension(o.parts.front()) != ".exr" && extension != ".png" && extension != ".exr")
    throw Error(fmt::format("{}: not a part of an upsampling table or of a PRT bake (and -o {} is no image, as a "
                            "reference render's parts are merged into)",
                            o.parts.front().string(), o.output.string()));
  checkReferenceOutputs(o.output, o.variance);
  const render::DisplaySettings display = referenceDisplay(o.display, o.output);
  requireWritable(o.output);
  if (!o.variance.empty()) requireWritable(o.variance);
  batch::MergedReference merged = batch::mergeReferenceParts(o.parts);
  writeReferenceImage(merged.image, merged.header.observer, merged.header.ev100, display, o.output, o.variance,
                      merged.header.cameraToXyz);
  fmt::print("merged {} parts into {} ({}x{}, {} paths per pixel)\n", o.parts.size(), o.output.string(),
             merged.header.width, merged.header.height, merged.header.samplesPerPixel);
}

}  // namespace prism::app
