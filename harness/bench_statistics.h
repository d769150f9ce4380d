// The statistics of `prism bench`: medians, the spread of per-round ratios, and the least-squares
// line of frame time against the wavelength count. On a shared machine the load drifts during a
// run, so the bench measures its configurations round by round and compares each with RGB
// within a round (both saw the same load), then summarises the rounds' ratios.
#pragma once

#include <vector>

namespace prism::harness {

// The middle value (the mean of the middle two for an even count); 0 for none.
double median(std::vector<double> values);

// The median's confidence interval from n samples, free of any assumed distribution: the order
// statistics x₍ₖ₎ and x₍ₙ₊₁₋ₖ₎ (1-based), k the largest rank with P(Binomial(n, ½) ≤ k − 1) ≤
// (1 − level)/2 — each sample falls below the true median with probability ½. At level 0.95 it
// needs 6 samples (even the extremes of 5 cover the median with 94 % only); with fewer, or an
// empty input, both ends are NaN.
struct Interval {
  double low = 0.0;
  double high = 0.0;
};
Interval medianConfidenceInterval(std::vector<double> values, double level = 0.95);

// test[r] / baseline[r] over the rounds r: the median ratio, its 95 % confidence interval (above)
// and the extreme rounds.
struct RatioSpread {
  double median = 0.0;
  Interval confidence;
  double min = 0.0;
  double max = 0.0;
};
// Throws std::invalid_argument unless both hold the same, non-zero number of rounds.
RatioSpread perRoundRatios(const std::vector<double>& test, const std::vector<double>& baseline);

// Least squares y = slope·x + intercept; the slope is 0 when every x is the same.
struct LinearFit {
  double slope = 0.0;
  double intercept = 0.0;
};
LinearFit linearFit(const std::vector<double>& x, const std::vector<double>& y);

}  // namespace prism::harness
