// What every cache of Prism's (the upsampling tables, wavelength sets, PRT transfers and skies)
// does alike with its folder: refuse a folder where an entry goes, before the work the entry
// holds, and keep the folder bounded.
#pragma once

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <string_view>

namespace prism {

// Error "ENTRY: is a folder where the cache keeps WHAT; remove it" when a folder has the entry's
// name: writeFileAtomically never replaces one, so the work before the write would be lost.
void requireNoFolderAtEntry(const std::filesystem::path& entry, std::string_view what);

// Removes the oldest files (by modification time) whose name ends in `extension` from `folder`
// until at most `maxEntries` remain and they hold at most `maxBytes` together; the newest is
// always kept. Errors are ignored: another process may be pruning too.
void pruneCacheFolder(const std::filesystem::path& folder, std::string_view extension, std::size_t maxEntries,
                      std::uintmax_t maxBytes);

}  // namespace prism
