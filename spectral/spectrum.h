// Spectra as Prism stores them.
//
// Spectrum: the dense form every computation uses, 471 samples at 1 nm over 360–830 nm (the
// domain of the CIE 1931 tables). Between samples a Spectrum is piecewise linear, outside the
// domain it is zero, and its integral is the trapezoid rule over the samples: the exact integral
// of that piecewise-linear function, so that any unbiased wavelength sampling converges to it.
//
// TabulatedSpectrum: data as published (any increasing wavelengths, any spacing), piecewise linear
// between its samples. Resampling onto the dense grid takes the table's value at each 1 nm node
// when every sample lies on a whole nanometre (the CIE's 1 nm and 5 nm tables, exact); a table
// with any sample between whole nanometres (a spectrometer's 0.1 nm lamp lines, the LSPDD lamp's
// 0.5 nm, measured indices) gives each node instead its average under the dense grid's hat
// function, which keeps the table's integral and centroid over 360–830 nm and its range of
// values: a mercury line between 546 and 547 nm keeps its energy instead of falling between two
// nodes. Beyond the table's ends the Extrapolation rule of the table applies (Zero for emitters
// and sensors, whose response outside the measured band is unknown and taken as none; Clamp for
// reflectances, whose last measured value is the best estimate of the next).
#pragma once

#include <array>
#include <cstddef>
#include <functional>
#include <span>
#include <string>
#include <vector>

#include <glm/vec3.hpp>

namespace prism {

inline constexpr int kLambdaMinNm = 360;
inline constexpr int kLambdaMaxNm = 830;
inline constexpr int kSpectrumSamples = kLambdaMaxNm - kLambdaMinNm + 1;

class Spectrum {
 public:
  Spectrum() { mValues.fill(0.0); }
  static Spectrum constant(double value);
  static Spectrum fromFunction(const std::function<double(double lambdaNm)>& f);

  // Value at the 1 nm node i (wavelength kLambdaMinNm + i).
  double operator[](int i) const { return mValues[static_cast<std::size_t>(i)]; }
  double& operator[](int i) { return mValues[static_cast<std::size_t>(i)]; }
  // Piecewise-linear value at any wavelength; zero outside [360, 830] nm.
  double at(double lambdaNm) const;
  // ∫ s(λ) dλ over 360–830 nm (trapezoid rule at 1 nm), in the spectrum's unit × nm.
  double integral() const;
  double maxValue() const;
  std::span<const double> values() const { return mValues; }

  Spectrum& operator*=(const Spectrum& other);
  Spectrum& operator*=(double factor);
  Spectrum& operator+=(const Spectrum& other);
  friend Spectrum operator*(Spectrum a, const Spectrum& b) { return a *= b; }
  friend Spectrum operator*(Spectrum a, double factor) { return a *= factor; }
  friend Spectrum operator*(double factor, Spectrum a) { return a *= factor; }
  friend Spectrum operator+(Spectrum a, const Spectrum& b) { return a += b; }
  friend bool operator==(const Spectrum& a, const Spectrum& b) = default;

 private:
  std::array<double, kSpectrumSamples> mValues;
};

enum class Extrapolation { Zero, Clamp };

class TabulatedSpectrum {
 public:
  // Wavelengths strictly increasing, at least two samples, same count as values, every number
  // finite: Error otherwise.
  TabulatedSpectrum(std::vector<double> lambdasNm, std::vector<double> values,
                    Extrapolation extrapolation);

  double at(double lambdaNm) const;
  Spectrum toDense() const;
  std::span<const double> lambdasNm() const { return mLambdasNm; }
  std::span<const double> values() const { return mValues; }

 private:
  // The value at lambdaNm of the linear piece of this table's function that holds `inside`.
  double onPieceOf(double inside, double lambdaNm) const;
  // ∫ f·hat / ∫ hat over [node − 1, node + 1] ∩ [360, 830] nm, f this table's function.
  double hatAverage(int node) const;

  std::vector<double> mLambdasNm;
  std::vector<double> mValues;
  Extrapolation mExtrapolation;
};

// Planck's law: spectral radiance of a black body, in W·sr⁻¹·m⁻²·nm⁻¹, with the CODATA 2018
// constants h, c, k_B (exact in SI since 2019). Wavelength in vacuum.
double planckRadianceWPerSrM2Nm(double lambdaNm, double temperatureK);
Spectrum blackbody(double temperatureK);

// Jakob–Hanika sigmoid-polynomial reflectance (shaders/shared/sigmoid.glsl) on the dense grid:
// the raw model, and Prism's upsampled reflectance (flat outside [380, 730] nm).
Spectrum sigmoidSpectrum(const glm::vec3& coeffs);
Spectrum upsampledReflectanceSpectrum(const glm::vec3& coeffs);
// The thesis's naive box upsampling (shaders/shared/box_upsampling.glsl) of an albedo, each
// channel clamped to [0, 1] (NaN read as 0).
Spectrum boxReflectanceSpectrum(const glm::vec3& rgb);

}  // namespace prism
