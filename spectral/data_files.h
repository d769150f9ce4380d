// Where Prism finds its data/ folder at run time: $PRISM_DATA_DIR if set, else the source tree
// it was built from, else the installed share/prism/data. Never anything outside these.
#pragma once

#include <filesystem>
#include <string_view>

namespace prism {

std::filesystem::path dataDirectory();
// Path of a file in data/; Error naming the file and the folder searched when it is missing.
std::filesystem::path dataFile(std::string_view name);

}  // namespace prism
