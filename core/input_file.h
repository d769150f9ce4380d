// Inputs checked before they are opened, so that every reader refuses the same things in one
// line: a missing path, a folder, and a device or a socket — /dev/zero never ends, and commands
// that read it whole grew by a gigabyte every few seconds until killed.
#pragma once

#include <filesystem>
#include <string_view>

namespace prism {

// Error "PATH: cannot open: no such file", "PATH: is a folder, not WHAT" or "PATH: not a regular
// file (a device or a socket), not WHAT" (`what` with its article: "a nebula scene"). A pipe
// (`<(…)`) passes: it is the user's own stream.
void requireInputFile(const std::filesystem::path& path, std::string_view what);

}  // namespace prism
