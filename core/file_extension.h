// A file's extension in lower case ("x.PNG" → ".png"): what Prism picks a format by, so that a
// name written in capitals reads and writes the same format as in small letters.
#pragma once

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <string>

namespace prism {

inline std::string lowercaseExtension(const std::filesystem::path& file) {
  std::string extension = file.extension().string();
  std::transform(extension.begin(), extension.end(), extension.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return extension;
}

}  // namespace prism
