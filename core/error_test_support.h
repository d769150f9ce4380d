// For tests: the message of the prism::Error a callable throws, failing the test when none is
// thrown (compare it whole, so that a test pins the file, the place and the wording).
#pragma once

#include <string>

#include <gtest/gtest.h>

#include "core/error.h"

namespace prism {

template <typename F>
std::string errorOf(F f) {
  try {
    f();
  } catch (const Error& e) {
    return e.what();
  }
  ADD_FAILURE() << "no prism::Error thrown";
  return {};
}

}  // namespace prism
