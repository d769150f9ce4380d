#include "core/cache_folder.h"

#include <algorithm>
#include <cctype>
#include <functional>
#include <string>
#include <tuple>
#include <vector>

#include "core/error.h"

namespace prism {
namespace {

bool isEntryName(std::string_view name, std::string_view prefix, std::string_view extension) {
  if (name.size() <= prefix.size() + extension.size() || !name.starts_with(prefix) || !name.ends_with(extension))
    return false;
  const std::string_view key = name.substr(prefix.size(), name.size() - prefix.size() - extension.size());
  return std::all_of(key.begin(), key.end(), [](unsigned char c) { return std::isxdigit(c) != 0; });
}

}  // namespace

void requireNoFolderAtEntry(const std::filesystem::path& entry, std::string_view what) {
  std::error_code ec;
  if (std::filesystem::is_directory(entry, ec))
    throw Error(entry.string() + ": is a folder where the cache keeps " + std::string(what) + "; remove it");
}

void touchCacheEntry(const std::filesystem::path& entry) {
  std::error_code ec;  // a read-only cache is still read
  std::filesystem::last_write_time(entry, std::filesystem::file_time_type::clock::now(), ec);
}

void pruneCacheFolder(const std::filesystem::path& folder, std::string_view prefix, std::string_view extension,
                      std::size_t maxEntries, std::uintmax_t maxBytes) {
  std::error_code ec;
  std::vector<std::tuple<std::filesystem::file_time_type, std::uintmax_t, std::filesystem::path>> entries;
  for (std::filesystem::directory_iterator it(folder, ec), end; !ec && it != end; it.increment(ec)) {
    std::error_code kind;
    if (isEntryName(it->path().filename().string(), prefix, extension) && it->is_regular_file(kind))
      entries.emplace_back(it->last_write_time(kind), it->file_size(kind), it->path());
  }
  std::sort(entries.begin(), entries.end(), std::greater<>());  // newest first
  std::uintmax_t bytes = 0;
  for (std::size_t i = 0; i < entries.size(); ++i) {
    bytes += std::get<1>(entries[i]);
    if (i > 0 && (i >= maxEntries || bytes > maxBytes)) std::filesystem::remove(std::get<2>(entries[i]), ec);
  }
}

}  // namespace prism
