// What Prism's caches do alike with their folders: refuse a folder where an entry goes, before
// the work the entry holds (the upsampling tables, wavelength sets, PRT transfers and skies), and
// keep a folder bounded, the entries least recently used going first (PRT's transfers and skies).
#pragma once

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <string_view>

namespace prism {

// Error "ENTRY: is a folder where the cache keeps WHAT; remove it" when a folder has the entry's
// name: writeFileAtomically never replaces one, so the work before the write would be lost.
void requireNoFolderAtEntry(const std::filesystem::path& entry, std::string_view what);

// An entry read from the cache is used: its modification time is now, so that pruning takes the
// entries least recently used (an entry read at every run, written long ago, went first).
void touchCacheEntry(const std::filesystem::path& entry);

// Removes the least recently used entries of `folder` — files named PREFIX, hex digits, EXTENSION,
// the names the cache gives them (anything else in the folder is the user's) — until at most
// `maxEntries` remain and they hold at most `maxBytes` together; the newest is always kept.
// Errors are ignored: another process may be pruning too.
void pruneCacheFolder(const std::filesystem::path& folder, std::string_view prefix, std::string_view extension,
                      std::size_t maxEntries, std::uintmax_t maxBytes);

}  // namespace prism
