// The two kinds of failure in Prism, kept apart (STYLE.md §10):
// - prism::Error: bad user input or data (a file, a name, a number out of range). Its message is
//   one line that names the thing and, for files, file:line[:column]; the CLI prints it and
//   exits non-zero.
// - PRISM_CHECK: a broken invariant inside Prism (a bug). Always on; prints both the expression
//   and where, then aborts.
#pragma once

#include <cstdio>
#include <cstdlib>
#include <stdexcept>
#include <string>

namespace prism {

class Error : public std::runtime_error {
 public:
  explicit Error(const std::string& message) : std::runtime_error(message) {}
};

}  // namespace prism

#define PRISM_CHECK(condition)                                                             \
  do {                                                                                     \
    if (!(condition)) {                                                                    \
      std::fprintf(stderr, "%s:%d: PRISM_CHECK failed: %s\n", __FILE__, __LINE__, #condition); \
      std::abort();                                                                        \
    }                                                                                      \
  } while (false)
