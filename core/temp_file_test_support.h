// For tests: a file of the given text in GoogleTest's temporary folder, to be read back by the
// code under test.
#pragma once

#include <filesystem>
#include <fstream>
#include <string>

#include <gtest/gtest.h>

namespace prism {

inline std::filesystem::path writeTempFile(const std::string& name, const std::string& text) {
  std::filesystem::path p = std::filesystem::path(::testing::TempDir()) / name;
  std::ofstream(p) << text;
  return p;
}

}  // namespace prism
