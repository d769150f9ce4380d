// The running maximum of error measures, for tests and fits: a non-finite error (a NaN or
// infinite pixel, a quotient by a zero reference) counts as infinitely large. std::max(worst,
// NaN) returns `worst`, so a maximum taken with it lets an image of NaNs pass any bound.
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>

namespace prism {

inline double worstOf(double worst, double error) {
  return std::isfinite(error) ? std::max(worst, error) : std::numeric_limits<double>::infinity();
}

}  // namespace prism
