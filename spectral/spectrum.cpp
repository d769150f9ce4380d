#include "spectral/spectrum.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "shared_cpp.h"
#include "core/error.h"

namespace prism::shared {
#include "box_upsampling.glsl"
#include "sigmoid.glsl"
}

namespace prism {

Spectrum Spectrum::constant(double value) {
  Spectrum s;
  for (int i = 0; i < kSpectrumSamples; ++i) s[i] = value;
  return s;
}

Spectrum Spectrum::fromFunction(const std::function<double(double)>& f) {
  Spectrum s;
  for (int i = 0; i < kSpectrumSamples; ++i) s[i] = f(kLambdaMinNm + i);
  return s;
}

double Spectrum::at(double lambdaNm) const {
  if (!(lambdaNm >= kLambdaMinNm && lambdaNm <= kLambdaMaxNm)) return 0.0;
  double x = lambdaNm - kLambdaMinNm;
  int i = std::min(static_cast<int>(x), kSpectrumSamples - 2);
  double t = x - i;
  return (*this)[i] * (1.0 - t) + (*this)[i + 1] * t;
}

double Spectrum::integral() const {
  double sum = 0.5 * (mValues.front() + mValues.back());
  for (int i = 1; i < kSpectrumSamples - 1; ++i) sum += (*this)[i];
  return sum;  // × 1 nm
}

double Spectrum::maxValue() const { return *std::max_element(mValues.begin(), mValues.end()); }

Spectrum& Spectrum::operator*=(const Spectrum& other) {
  for (int i = 0; i < kSpectrumSamples; ++i) (*this)[i] *= other[i];
  return *this;
}

Spectrum& Spectrum::operator*=(double factor) {
  for (double& v : mValues) v *= factor;
  return *this;
}

Spectrum& Spectrum::operator+=(const Spectrum& other) {
  for (int i = 0; i < kSpectrumSamples; ++i) (*this)[i] += other[i];
  return *this;
}

TabulatedSpectrum::TabulatedSpectrum(std::vector<double> lambdasNm, std::vector<double> values,
                                     Extrapolation extrapolation)
    : mLambdasNm(std::move(lambdasNm)), mValues(std::move(values)), mExtrapolation(extrapolation) {
  // A library's caller may hand any table: what the CSV reader refuses with its file and line is
  // refused here too, as an Error (it aborted on an internal check, and took NaN values).
  if (mLambdasNm.size() != mValues.size())
    throw Error("a tabulated spectrum needs as many values as wavelengths, not " + std::to_string(mValues.size()) +
                " for " + std::to_string(mLambdasNm.size()));
  if (mLambdasNm.size() < 2)
    throw Error("a tabulated spectrum needs at least two wavelengths, not " + std::to_string(mLambdasNm.size()));
  if (std::adjacent_find(mLambdasNm.begin(), mLambdasNm.end(), [](double a, double b) { return !(a < b); }) !=
          mLambdasNm.end() ||
      !std::isfinite(mLambdasNm.front()) || !std::isfinite(mLambdasNm.back()))
    throw Error("a tabulated spectrum's wavelengths must be finite and increase strictly");
  if (!std::all_of(mValues.begin(), mValues.end(), [](double v) { return std::isfinite(v); }))
    throw Error("a tabulated spectrum's values must be finite");
}

double TabulatedSpectrum::at(double lambdaNm) const {
  if (lambdaNm < mLambdasNm.front())
    return mExtrapolation == Extrapolation::Clamp ? mValues.front() : 0.0;
  if (lambdaNm > mLambdasNm.back())
    return mExtrapolation == Extrapolation::Clamp ? mValues.back() : 0.0;
  auto upper = std::upper_bound(mLambdasNm.begin(), mLambdasNm.end(), lambdaNm);
  if (upper == mLambdasNm.end()) return mValues.back();
  std::size_t hi = static_cast<std::size_t>(upper - mLambdasNm.begin());
  std::size_t lo = hi - 1;
  double t = (lambdaNm - mLambdasNm[lo]) / (mLambdasNm[hi] - mLambdasNm[lo]);
  return mValues[lo] * (1.0 - t) + mValues[hi] * t;
}

double TabulatedSpectrum::onPieceOf(double inside, double lambdaNm) const {
  if (inside < mLambdasNm.front() || inside > mLambdasNm.back()) return at(inside);  // constant out there
  const auto hi = static_cast<std::size_t>(std::upper_bound(mLambdasNm.begin(), mLambdasNm.end(), inside) -
                                           mLambdasNm.begin());
  const std::size_t lo = hi - 1;
  const double t = (lambdaNm - mLambdasNm[lo]) / (mLambdasNm[hi] - mLambdasNm[lo]);
  return mValues[lo] * (1.0 - t) + mValues[hi] * t;
}

double TabulatedSpectrum::hatAverage(int node) const {
  // f is linear on each piece of the hat's support between knots (and constant outside the
  // table), so f·hat is a quadratic there, which Simpson's rule integrates exactly. The average
  // lies within f's extremes on the support, its pieces' ends; held there against rounding (a
  // reflectance of 1 stays 1, not 1 + 1e-14).
  const double centre = node;
  double sum = 0.0, weight = 0.0;
  double lowest = std::numeric_limits<double>::infinity(), highest = -lowest;
  auto hat = [centre](double l) { return 1.0 - std::abs(l - centre); };
  for (double outer : {centre - 1.0, centre + 1.0}) {
    if (outer < kLambdaMinNm || outer > kLambdaMaxNm) continue;
    const double lo = std::min(centre, outer), hi = std::max(centre, outer);
    std::vector<double> cuts{lo};
    cuts.insert(cuts.end(), std::upper_bound(mLambdasNm.begin(), mLambdasNm.end(), lo),
                std::lower_bound(mLambdasNm.begin(), mLambdasNm.end(), hi));
    cuts.push_back(hi);
    for (std::size_t k = 0; k + 1 < cuts.size(); ++k) {
      const double a = cuts[k], b = cuts[k + 1], m = 0.5 * (a + b);
      const double fa = onPieceOf(m, a), fm = onPieceOf(m, m), fb = onPieceOf(m, b);  // f may jump at the ends
      sum += (b - a) / 6.0 * (fa * hat(a) + 4.0 * fm * hat(m) + fb * hat(b));
      lowest = std::min({lowest, fa, fb});
      highest = std::max({highest, fa, fb});
    }
    weight += 0.5;
  }
  return std::clamp(sum / weight, lowest, highest);
}

Spectrum TabulatedSpectrum::toDense() const {
  // One rule for the whole table: nodes of both kinds side by side would not keep its integral
  // (a point value differs from its hat average by the local curvature, which need not cancel).
  const bool offWholeNanometres =
      std::any_of(mLambdasNm.begin(), mLambdasNm.end(), [](double l) { return l != std::floor(l); });
  Spectrum dense;
  for (int i = 0; i < kSpectrumSamples; ++i) {
    const int node = kLambdaMinNm + i;
    dense[i] = offWholeNanometres ? hatAverage(node) : at(node);
  }
  return dense;
}

double planckRadianceWPerSrM2Nm(double lambdaNm, double temperatureK) {
  constexpr double h = 6.62607015e-34;  // J·s
  constexpr double c = 299792458.0;     // m/s
  constexpr double kB = 1.380649e-23;   // J/K
  double lambdaM = lambdaNm * 1e-9;
  double perMetre = 2.0 * h * c * c / (std::pow(lambdaM, 5) * std::expm1(h * c / (lambdaM * kB * temperatureK)));
  return perMetre * 1e-9;
}

Spectrum blackbody(double temperatureK) {
  if (!(temperatureK > 0.0 && std::isfinite(temperatureK)))
    throw Error("blackbody: temperature must be a positive number of kelvin, got " + shortestNumber(temperatureK));
  return Spectrum::fromFunction(
      [temperatureK](double lambdaNm) { return planckRadianceWPerSrM2Nm(lambdaNm, temperatureK); });
}

Spectrum sigmoidSpectrum(const glm::vec3& coeffs) {
  return Spectrum::fromFunction([&coeffs](double lambdaNm) {
    return static_cast<double>(shared::sigmoidSpectrum(coeffs, static_cast<float>(lambdaNm)));
  });
}

}  // namespace prism

namespace prism {

Spectrum upsampledReflectanceSpectrum(const glm::vec3& coeffs) {
  return Spectrum::fromFunction([&coeffs](double lambdaNm) {
    return static_cast<double>(shared::upsampledReflectance(coeffs, static_cast<float>(lambdaNm)));
  });
}

Spectrum boxReflectanceSpectrum(const glm::vec3& rgb) {
  glm::vec3 albedo;
  for (int c = 0; c < 3; ++c) albedo[c] = std::isnan(rgb[c]) ? 0.0f : std::clamp(rgb[c], 0.0f, 1.0f);
  return Spectrum::fromFunction([&albedo](double lambdaNm) {
    return static_cast<double>(shared::boxReflectance(albedo, static_cast<float>(lambdaNm)));
  });
}

}  // namespace prism
