#include "harness/bench_statistics.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace prism::harness {

double median(std::vector<double> values) {
  if (values.empty()) return 0.0;
  std::sort(values.begin(), values.end());
  std::size_t n = values.size();
  return n % 2 ? values[n / 2] : 0.5 * (values[n / 2 - 1] + values[n / 2]);
}

Interval medianConfidenceInterval(std::vector<double> values, double level) {
  if (!(level > 0.0 && level < 1.0)) throw std::invalid_argument("medianConfidenceInterval: a level in (0, 1)");
  const std::size_t n = values.size();
  const double tail = 0.5 * (1.0 - level);
  // k = the number of ranks i (from 0) whose cumulative binomial probability P(B ≤ i) stays within
  // the tail: the interval drops the k − 1 lowest and highest samples.
  std::size_t k = 0;
  double cumulative = 0.0;
  const double logHalfPower = static_cast<double>(n) * std::log(0.5);
  for (std::size_t i = 0; i <= n / 2; ++i) {
    const double logChoose = std::lgamma(static_cast<double>(n) + 1.0) - std::lgamma(static_cast<double>(i) + 1.0) -
                             std::lgamma(static_cast<double>(n - i) + 1.0);
    cumulative += std::exp(logChoose + logHalfPower);
    if (cumulative > tail) break;
    k = i + 1;
  }
  if (k == 0) return {std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::quiet_NaN()};
  std::sort(values.begin(), values.end());
  return {values[k - 1], values[n - k]};
}

RatioSpread perRoundRatios(const std::vector<double>& test, const std::vector<double>& baseline) {
  if (test.empty() || test.size() != baseline.size())
    throw std::invalid_argument("perRoundRatios: the same, non-zero number of rounds on both sides");
  std::vector<double> ratios;
  for (std::size_t r = 0; r < test.size(); ++r) ratios.push_back(test[r] / baseline[r]);
  auto [min, max] = std::minmax_element(ratios.begin(), ratios.end());
  return {median(ratios), medianConfidenceInterval(ratios), *min, *max};
}

LinearFit linearFit(const std::vector<double>& x, const std::vector<double>& y) {
  if (x.empty() || x.size() != y.size()) throw std::invalid_argument("linearFit: as many x as y, at least one");
  double mx = 0, my = 0;
  for (std::size_t i = 0; i < x.size(); ++i) {
    mx += x[i];
    my += y[i];
  }
  mx /= static_cast<double>(x.size());
  my /= static_cast<double>(x.size());
  double sxy = 0, sxx = 0;
  for (std::size_t i = 0; i < x.size(); ++i) {
    sxy += (x[i] - mx) * (y[i] - my);
    sxx += (x[i] - mx) * (x[i] - mx);
  }
  double slope = sxx > 0 ? sxy / sxx : 0.0;
  return {slope, my - slope * mx};
}

}  // namespace prism::harness
