// Names are case-sensitive (D65, F11, Au, nikon_d850), and "d65" was refused with a list to go
// and read: the refusal names the spelling the user most likely meant.
#pragma once

#include <algorithm>
#include <cctype>
#include <string>
#include <string_view>

namespace prism {

// " (did you mean 'D65'?)" when one of `names` is `given` but for letter case, else "".
template <class Names>
std::string caseHint(std::string_view given, const Names& names) {
  auto lower = [](unsigned char c) { return std::tolower(c); };
  for (const auto& name : names) {
    const std::string_view n = name;
    if (n != given && std::ranges::equal(n, given, {}, lower, lower)) return " (did you mean '" + std::string(n) + "'?)";
  }
  return "";
}

}  // namespace prism
