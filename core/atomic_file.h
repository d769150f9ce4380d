// Writing outputs and caches so that a reader never sees half a file: the bytes go to a
// temporary file beside the target, which is then renamed over it (atomic on POSIX).
#pragma once

#include <filesystem>
#include <string_view>

namespace prism {

// Through a symbolic link, the link's target is written and the link kept. Creates missing parent
// folders. Error naming the path when anything fails, when a folder,
// device, pipe or socket is there (never replaced), or when the path has no file name (empty, or
// ending in a separator); the temporary file is removed then. A write that succeeds removes the
// temporaries of earlier writes of the path killed before their rename, an hour old or more.
void writeFileAtomically(const std::filesystem::path& path, std::string_view bytes);

// Before long work whose result goes to `path` (a table, a render): Error "PATH: cannot write:
// why" (or "PATH: is a folder") unless a file can be created where it goes — in its folder, or
// in the nearest existing folder above when folders are still to be made (made by
// writeFileAtomically, not here); "PATH: is not a plain file" for a device, pipe or socket, which
// neither function replaces; and a path with no file name, as writeFileAtomically refuses it.
// Leaves nothing behind.
void requireWritable(const std::filesystem::path& path);

// requireWritable for an output folder (a gallery): Error "FOLDER: is a file, not a folder" when
// a file has its name, else unless files can be created in it or, while it is still to be made,
// in the nearest existing folder above it ("cannot write: X is not a folder" when that is a file).
void requireWritableFolder(const std::filesystem::path& folder);

// Before writing `output`: Error "OUTPUT: is also ROLE; write it to another file" when it names
// the same file as `other` (an input the command reads, or another of its outputs), through
// links and `..` too. An empty `other` is none.
void requireOtherFile(const std::filesystem::path& output, const std::filesystem::path& other,
                      std::string_view role);

}  // namespace prism
