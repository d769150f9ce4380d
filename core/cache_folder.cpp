#include "core/cache_folder.h"

#include <algorithm>
#include <string>
#include <tuple>
#include <vector>

#include "core/error.h"

namespace prism {

void requireNoFolderAtEntry(const std::filesystem::path& entry, std::string_view what) {
  std::error_code ec;
  if (std::filesystem::is_directory(entry, ec))
    throw Error(entry.string() + ": is a folder where the cache keeps " + std::string(what) + "; remove it");
}

void pruneCacheFolder(const std::filesystem::path& folder, std::string_view extension, std::size_t maxEntries,
                      std::uintmax_t maxBytes) {
  std::error_code ec;
  std::vector<std::tuple<std::filesystem::file_time_type, std::uintmax_t, std::filesystem::path>> entries;
  for (const auto& e : std::filesystem::directory_iterator(folder, ec)) {
    std::error_code kind;
    if (e.path().extension() == extension && e.is_regular_file(kind))
      entries.emplace_back(e.last_write_time(kind), e.file_size(kind), e.path());
  }
  std::sort(entries.begin(), entries.end(), std::greater<>());  // newest first
  std::uintmax_t bytes = 0;
  for (std::size_t i = 0; i < entries.size(); ++i) {
    bytes += std::get<1>(entries[i]);
    if (i > 0 && (i >= maxEntries || bytes > maxBytes)) std::filesystem::remove(std::get<2>(entries[i]), ec);
  }
}

}  // namespace prism
