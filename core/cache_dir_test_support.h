// For tests: a cache folder of their own. While a ScopedCacheDirectory lives, PRISM_CACHE_DIR names
// a new, empty folder in GoogleTest's temporary folder (unique to the process and the name); its
// destructor puts the variable back as it was and removes the folder.
#pragma once

#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <string>

#include <gtest/gtest.h>

namespace prism {

class ScopedCacheDirectory {
 public:
  explicit ScopedCacheDirectory(const std::string& name)
      : mPath(std::filesystem::path(::testing::TempDir()) / (name + "_" + std::to_string(::getpid()))) {
    std::filesystem::remove_all(mPath);
    if (const char* previous = std::getenv("PRISM_CACHE_DIR")) mPrevious = previous;
    mHadPrevious = std::getenv("PRISM_CACHE_DIR") != nullptr;
    ::setenv("PRISM_CACHE_DIR", mPath.c_str(), 1);
  }
  ~ScopedCacheDirectory() {
    if (mHadPrevious) ::setenv("PRISM_CACHE_DIR", mPrevious.c_str(), 1);
    else ::unsetenv("PRISM_CACHE_DIR");
    std::error_code ec;
    std::filesystem::remove_all(mPath, ec);
  }
  ScopedCacheDirectory(const ScopedCacheDirectory&) = delete;
  ScopedCacheDirectory& operator=(const ScopedCacheDirectory&) = delete;

  const std::filesystem::path& path() const { return mPath; }

 private:
  std::filesystem::path mPath;
  std::string mPrevious;
  bool mHadPrevious = false;
};

}  // namespace prism
