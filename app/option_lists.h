// A command line's lists: of numbers ("0.2,0.4,0.6", or "380:780:5" with another separator), as
// the options that take several numbers give them, and of names ("spheres_d65,reef_5m").
#pragma once

#include <string>
#include <vector>

namespace prism::app {

// Finite numbers within ±schema::kFloatInputLimit (a scene's limit) separated by `separator`;
// Error naming the option otherwise.
std::vector<double> parseNumbers(const std::string& text, const std::string& option, char separator = ',');

// One such number: Error naming the option otherwise, a list too ("--ev 3,4" took the 3).
double parseNumber(const std::string& text, const std::string& option);

// Names separated by commas, each non-empty: Error naming the option otherwise. Parsed here, not
// by CLI11's delimiter, which took the next argument for a name after "--only ,".
std::vector<std::string> parseNames(const std::string& text, const std::string& option);

}  // namespace prism::app
