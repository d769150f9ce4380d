// A library's refusal of a value, said with the option the user gave it in: "unknown colour
// space 'foo'" from prism::colourSpace becomes "--gamut: unknown colour space 'foo'", so that a
// command line with several names says which one is wrong.
#pragma once

#include <string_view>

#include <fmt/format.h>

#include "core/error.h"

namespace prism::app {

// make()'s value; its Error again, prefixed by "OPTION: ".
template <class Make>
auto fromOption(std::string_view option, Make&& make) -> decltype(make()) {
  try {
    return make();
  } catch (const Error& e) {
    throw Error(fmt::format("{}: {}", option, e.what()));
  }
}

}  // namespace prism::app
