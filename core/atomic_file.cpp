#include "core/atomic_file.h"

#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <string>

#include "core/error.h"

namespace prism {
namespace {

// A folder, device, pipe or socket where the file would go: the rename would replace it. And no
// file name at all: "x.bin/" made the folder x.bin before its write failed.
void requireNoOtherKindOfFile(const std::filesystem::path& path) {
  if (path.empty()) throw Error("an output's file name is empty");
  if (!path.has_filename())
    throw Error(path.string() + ": ends in a separator, so it names a folder; give a file to write");
  std::error_code ec;
  const std::filesystem::file_status s = std::filesystem::status(path, ec);
  if (std::filesystem::is_directory(s)) throw Error(path.string() + ": is a folder");
  if (std::filesystem::exists(s) && !std::filesystem::is_regular_file(s))
    throw Error(path.string() + ": is not a plain file (a device, pipe or socket); Prism writes only plain files");
}

// Where `path` leads through symbolic links: the file a write must replace. Renamed over, the link
// itself became a plain file and its target kept the old bytes; `cp` and `>` write the target.
std::filesystem::path throughLinks(const std::filesystem::path& path) {
  std::filesystem::path at = path;
  std::error_code ec;
  for (int hops = 0; std::filesystem::is_symlink(std::filesystem::symlink_status(at, ec)); ++hops) {
    if (hops == 40) throw Error(path.string() + ": cannot write: too many levels of symbolic links");
    const std::filesystem::path target = std::filesystem::read_symlink(at, ec);
    if (ec) throw Error(path.string() + ": cannot write: " + ec.message());
    at = target.is_absolute() ? target : at.parent_path() / target;
  }
  return at;
}

// Through a link, the file that failed is named too: "LINK (→ TARGET)".
std::string shownWithTarget(const std::filesystem::path& path, const std::filesystem::path& file) {
  return file == path ? path.string() : path.string() + " (→ " + file.string() + ")";
}

// Error "PATH: cannot write: …" unless the nearest existing folder at or above `start` is a folder
// in which a file can be created (a probe, removed again).
void requireCreatableFrom(const std::filesystem::path& path, std::filesystem::path start) {
  std::error_code ec;
  while (!std::filesystem::exists(start, ec) && start.has_relative_path()) start = start.parent_path();
  if (!std::filesystem::is_directory(start, ec))
    throw Error(path.string() + ": cannot write: " + start.string() + " is not a folder");
  std::filesystem::path probe = start / (".prism-probe" + std::to_string(::getpid()));
  std::FILE* f = std::fopen(probe.c_str(), "wb");
  if (!f) throw Error(path.string() + ": cannot write: " + std::strerror(errno));
  std::fclose(f);
  std::filesystem::remove(probe, ec);
}

// The temporaries of earlier writes of `path` that were killed between write and rename (SIGKILL:
// an out-of-memory kill, a batch system's): "NAME.tmpPID" beside it, untouched for an hour — a
// live writer's is minutes old at most, whichever machine of a cluster writes it (its PID is not
// this machine's to ask). Best effort: what cannot be listed or removed is left.
void removeStaleTemporaries(const std::filesystem::path& path) {
  const std::string prefix = path.filename().string() + ".tmp";
  const auto hourAgo = std::filesystem::file_time_type::clock::now() - std::chrono::hours(1);
  std::error_code ec;
  const std::filesystem::path folder = path.has_parent_path() ? path.parent_path() : std::filesystem::path(".");
  for (std::filesystem::directory_iterator it(folder, ec), end; !ec && it != end; it.increment(ec)) {
    const std::filesystem::directory_entry& entry = *it;
    const std::string name = entry.path().filename().string();
    if (name.size() <= prefix.size() || name.compare(0, prefix.size(), prefix) != 0) continue;
    if (!std::all_of(name.begin() + static_cast<std::ptrdiff_t>(prefix.size()), name.end(),
                     [](unsigned char c) { return std::isdigit(c) != 0; }))
      continue;
    std::error_code age;
    if (entry.is_regular_file(age) && entry.last_write_time(age) < hourAgo && !age)
      std::filesystem::remove(entry.path(), age);
  }
}

}  // namespace

void writeFileAtomically(const std::filesystem::path& path, std::string_view bytes) {
  requireNoOtherKindOfFile(path);
  const std::filesystem::path file = throughLinks(path);
  const std::string shown = shownWithTarget(path, file);
  std::error_code ec;
  if (file.has_parent_path()) std::filesystem::create_directories(file.parent_path(), ec);
  if (ec) throw Error(shown + ": cannot create folder: " + ec.message());
  std::filesystem::path temp = file;
  temp += ".tmp" + std::to_string(::getpid());
  std::FILE* f = std::fopen(temp.c_str(), "wb");
  if (!f) throw Error(shown + ": cannot write: " + std::strerror(errno));
  bool ok = std::fwrite(bytes.data(), 1, bytes.size(), f) == bytes.size();
  ok = (std::fflush(f) == 0) && ok;
  ok = (::fsync(::fileno(f)) == 0) && ok;
  ok = (std::fclose(f) == 0) && ok;
  if (ok) std::filesystem::rename(temp, file, ec);
  if (!ok || ec) {
    std::string why = ec ? ec.message() : std::strerror(errno);
    std::filesystem::remove(temp, ec);
    throw Error(shown + ": cannot write: " + why);
  }
  removeStaleTemporaries(file);
}

void requireWritable(const std::filesystem::path& path) {
  requireNoOtherKindOfFile(path);
  std::error_code ec;
  const std::filesystem::path file = throughLinks(path);
  requireCreatableFrom(shownWithTarget(path, file), std::filesystem::absolute(file, ec).parent_path());
}

void requireWritableFolder(const std::filesystem::path& folder) {
  std::error_code ec;
  if (std::filesystem::exists(folder, ec) && !std::filesystem::is_directory(folder, ec))
    throw Error(folder.string() + ": is a file, not a folder; give a folder to write into");
  requireCreatableFrom(folder, std::filesystem::absolute(folder, ec));
}

void requireOtherFile(const std::filesystem::path& output, const std::filesystem::path& other,
                      std::string_view role) {
  if (output.empty() || other.empty()) return;
  std::error_code a, b;
  bool same = false;
  if (std::filesystem::exists(output, a) && std::filesystem::exists(other, b)) {
    same = std::filesystem::equivalent(output, other, a);
  } else {
    const std::filesystem::path x = std::filesystem::weakly_canonical(std::filesystem::absolute(output), a);
    const std::filesystem::path y = std::filesystem::weakly_canonical(std::filesystem::absolute(other), b);
    same = !a && !b && x == y;
  }
  if (same) throw Error(output.string() + ": is also " + std::string(role) + "; write it to another file");
}

}  // namespace prism
