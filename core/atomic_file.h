// Writing outputs and caches so that a reader never sees half a file: the bytes go to a
// temporary file beside the target, which is then renamed over it (atomic on POSIX).
#pragma once

#include <filesystem>
#include <string_view>

namespace prism {

// Creates missing parent folders. Error naming the path when anything fails; the temporary
// file is removed then.
void writeFileAtomically(const std::filesystem::path& path, std::string_view bytes);

}  // namespace prism
