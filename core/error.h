// The two kinds of failure in Prism, kept apart (STYLE.md §10):
// - prism::Error: bad user input or data (a file, a name, a number out of range). Its message is
//   one line that names the thing and, for files, the place (FileLocation: file:line[:column]);
//   the CLI prints it and exits non-zero.
// - PRISM_CHECK: a broken invariant inside Prism (a bug). Always on; prints both the expression
//   and where, then aborts.
#pragma once

#include <charconv>
#include <cstdio>
#include <cstdlib>
#include <stdexcept>
#include <string>
#include <string_view>

namespace prism {

// A place in a user's file, as editors and compilers print it: "FILE", "FILE:LINE" or
// "FILE:LINE:COLUMN" (1-based; 0 means not known).
struct FileLocation {
  std::string file;
  int line = 0;
  int column = 0;

  std::string str() const {
    std::string s = file;
    for (int n : {line, column}) {
      if (n <= 0) break;
      s += ':';
      s += std::to_string(n);
    }
    return s;
  }
};

// A number as a message quotes it, the shortest text that reads back the same: 0.01 and 3000,
// not std::to_string's 0.010000 and 3000.000000.
inline std::string shortestNumber(double value) {
  char text[32];
  const auto end = std::to_chars(text, text + sizeof text, value).ptr;
  return std::string(text, end);
}

// A user's text as a message quotes it: whole up to `max` bytes, else its first bytes and "..."
// (a 5 MB name is not echoed whole); control characters (a file's bytes quoted by a decoder, a
// line break) and bytes that are no UTF-8 (a PNG's first byte, quoted by the JSON parser, or a
// character cut by the limit) become '?', so the message stays one line of text.
inline std::string excerpt(std::string_view text, std::size_t max = 80) {
  std::string quoted(text.size() <= max ? text : text.substr(0, max - 3));
  for (std::size_t i = 0; i < quoted.size();) {
    const auto byte = [&](std::size_t at) { return static_cast<unsigned char>(quoted[at]); };
    const unsigned char c = byte(i);
    // The sequence's length by its lead byte (RFC 3629: C2–DF, E0–EF, F0–F4 lead 2, 3, 4 bytes).
    const std::size_t length = c < 0x80 ? 1 : c >= 0xc2 && c <= 0xdf ? 2 : c >= 0xe0 && c <= 0xef ? 3 : c >= 0xf0 && c <= 0xf4 ? 4 : 0;
    bool valid = length > 0 && i + length <= quoted.size();
    for (std::size_t k = 1; valid && k < length; ++k) valid = (byte(i + k) & 0xc0) == 0x80;
    if (!valid || c < 0x20 || c == 0x7f) {
      quoted[i++] = '?';
      continue;
    }
    i += length;
  }
  return text.size() <= max ? quoted : quoted + "...";
}

class Error : public std::runtime_error {
 public:
  explicit Error(const std::string& message) : std::runtime_error(message) {}
  // "FILE:LINE:COLUMN: message"
  Error(const FileLocation& where, const std::string& message) : std::runtime_error(where.str() + ": " + message) {}
};

}  // namespace prism

#define PRISM_CHECK(condition)                                                             \
  do {                                                                                     \
    if (!(condition)) {                                                                    \
      std::fprintf(stderr, "%s:%d: PRISM_CHECK failed: %s\n", __FILE__, __LINE__, #condition); \
      std::abort();                                                                        \
    }                                                                                      \
  } while (false)
