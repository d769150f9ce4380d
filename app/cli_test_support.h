// The prism executable run from a test: `run("ARGS")` gives its exit code, stdout and stderr.
// Shared by the CLI tests (cli_test.cpp, merge_test.cpp, reference_display_test.cpp,
// settings_parity_test.cpp).
#pragma once

#include <gtest/gtest.h>
#include <sys/wait.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

namespace prism::app::test {

struct Result {
  int exitCode = -1;
  std::string out, err;
};

inline std::string slurp(const std::filesystem::path& p) {
  std::ifstream in(p);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

// Runs `prism ARGS` through the shell (ARGS quoted by the caller) with an optional environment
// prefix; a crash (signal) shows up as exitCode -1.
inline Result run(const std::string& args, const std::string& env = "") {
  // One file per test: ctest runs tests of this binary in parallel processes.
  const auto* test = ::testing::UnitTest::GetInstance()->current_test_info();
  std::filesystem::path errFile = std::filesystem::path(::testing::TempDir()) /
                                  (std::string("prism_stderr_") + test->name() + ".txt");
  std::string command = env + " " + PRISM_EXECUTABLE + " " + args + " 2>" + errFile.string();
  Result r;
  FILE* pipe = popen(command.c_str(), "r");
  char buffer[4096];
  while (std::size_t n = std::fread(buffer, 1, sizeof buffer, pipe)) r.out.append(buffer, n);
  int status = pclose(pipe);
  r.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  r.err = slurp(errFile);
  return r;
}

}  // namespace prism::app::test
