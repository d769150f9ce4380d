// A file's extension in lower case ("x.PNG" → ".png"): what Prism picks a format by, so that a
// name written in capitals reads and writes the same format as in small letters; and the check
// that an output is named for the one format a command writes it in.
#pragma once

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <string>
#include <string_view>

#include <fmt/format.h>

#include "core/error.h"

namespace prism {

inline std::string lowercaseExtension(const std::filesystem::path& file) {
  std::string extension = file.extension().string();
  std::transform(extension.begin(), extension.end(), extension.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return extension;
}

// Error "OPTION FILE: the WHAT is written as an EXTENSION file" (OPTION left out when empty)
// unless FILE ends in EXTENSION (".svg"), in either case: an SVG in x.png would be no PNG.
inline void requireExtension(const std::filesystem::path& file, std::string_view extension, std::string_view option,
                             std::string_view what) {
  if (lowercaseExtension(file) == extension) return;
  if (file.empty())
    throw Error(fmt::format("{}the {}'s file name is empty", option.empty() ? "" : std::string(option) + ": ", what));
  // "an .svg", "a .png": the article of the first letter's name, as the extension is read out.
  const bool vowelSound = extension.size() > 1 && std::string_view("aefhilmnorsx").find(extension[1]) != std::string_view::npos;
  throw Error(fmt::format("{}{}: the {} is written as {} {} file", option.empty() ? "" : std::string(option) + " ",
                          file.string(), what, vowelSound ? "an" : "a", extension));
}

// Error "OPTION FILE: the WHAT is not an image; name it otherwise than .EXT" when FILE is named
// for an image format (.png, .exr, .hdr, .jpg, .jpeg): a table or a bake under such a name would
// be taken for an image by every viewer and by Prism's own image options.
inline void refuseImageExtension(const std::filesystem::path& file, std::string_view option, std::string_view what) {
  const std::string extension = lowercaseExtension(file);
  for (std::string_view image : {".png", ".exr", ".hdr", ".jpg", ".jpeg"}) {
    if (extension != image) continue;
    throw Error(fmt::format("{}{}: the {} is not an image; name it otherwise than {}",
                            option.empty() ? "" : std::string(option) + " ", file.string(), what, extension));
  }
}

}  // namespace prism
