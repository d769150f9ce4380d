// What every fuzz target shares: the input's bytes as a file (Prism's loaders read paths), and
// the rule the targets check besides memory safety — a loader given bad bytes throws only what the
// command line reports as bad input (prism::Error, std::filesystem::filesystem_error: exit 1), in
// one line of bounded length. Anything else escapes the target, and libFuzzer (or the corpus
// replay of fuzz_replay.cpp) reports it as a crash.
#pragma once

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <span>
#include <string_view>

namespace prism::fuzz {

// Writes the bytes to NAME in this process's scratch folder (under the system's temporary folder,
// made once, removed at exit) and returns its path. The same name is overwritten each call.
std::filesystem::path inputFile(std::span<const std::uint8_t> bytes, std::string_view name);

// The scratch folder itself, for targets that lay out several files (a scene and its glTF).
const std::filesystem::path& scratchFolder();

// Runs `load`; returns normally when it succeeds or throws a user-input error whose message is one
// line of at most kMaxMessageLength characters; aborts with the message otherwise.
void expectOnlyInputErrors(const std::function<void()>& load);

// How many loads expectOnlyInputErrors has seen rejected so far (the replay tells accepted inputs
// from rejected ones by it).
std::size_t rejectedLoads();

// An error message echoes at most about 80 characters of a value (core/error.h's excerpt) plus
// the file, the JSON pointer and what was expected.
inline constexpr std::size_t kMaxMessageLength = 1024;

}  // namespace prism::fuzz
