// OpenEXR's exception texts as Prism's errors quote them: on one line (its messages may hold line
// breaks) and at most 200 characters. For the EXR readers and writers of this layer.
#pragma once

#include <algorithm>
#include <string>

#include "core/error.h"

namespace prism::imaging {

inline std::string openExrMessage(std::string text) {
  std::replace(text.begin(), text.end(), '\n', ' ');
  return excerpt(text, 200);
}

}  // namespace prism::imaging
