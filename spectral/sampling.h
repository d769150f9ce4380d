// Wavelength sampling: which wavelengths a spectral pass evaluates, with their pdfs, in batches
// of four (one vec4 on the GPU), and the integration matrices that turn each batch of radiance
// samples into XYZ or camera RGB.
//
// Every strategy is an estimator of ∫ L(λ)·c̄(λ) dλ over [λmin, λmax]:
//   Σ_i L(λ_i)·c̄(λ_i) / (n·pdf(λ_i)),
// so one weight rule, w_i = 1 / (n·pdf_i), serves them all:
//   Uniform     λ_i at the midpoints of n equal strata, pdf = 1/(λmax − λmin): the midpoint
//               Riemann sum, deterministic.
//   Stratified  one uniform jitter per stratum (from the seed, e.g. per frame or per pixel and
//               frame; shaders/shared/random.glsl): unbiased, converging under accumulation.
//   Rotated     the uniform grid shifted by one offset per frame, the golden-ratio sequence
//               frac(½ + seed·0.618…): each frame has the midpoint rule's small error, and
//               frames accumulated fill the gaps evenly, so the mean converges to the integral
//               about as 1/frames (independent jitter converges as 1/√frames). Seed 0 is
//               Uniform. For renderers accumulating frames while nothing moves.
//   Importance  stratified in the CDF of the observer's summed response x̄+ȳ+z̄ (piecewise
//               constant per 1 nm bin, floored at 1e-3 of its mean so no wavelength has pdf 0).
//   Lights      the rotated grid (Rotated's offset per frame) in the CDF of the scene's emission
//               × the observer's curves (each an equal share), with 10 % of Importance's pdf
//               mixed in (spectral/wavelength_pdf.h): the samples go where the lamps emit what
//               the observer sees, one frame is close under narrow or spiky lamps, and frames
//               accumulate at the rotated grid's rate. The sampler is built once per change of
//               the lights (the emission is its input).
//   Optimised   n fixed wavelengths and a full 3 × n matrix fitted for the scene's lights
//               (spectral/wavelength_fit.h): deterministic, the same every frame, closest in one
//               frame but biased (accumulating does not converge beyond it). Its matrix is the
//               fit's, not c̄(λ)/(n·pdf): callers take matrices from WavelengthSampler::matrices.
#pragma once

#include <array>
#include <cmath>
#include <cstdint>
#include <optional>
#include <string_view>
#include <vector>

#include <Eigen/Core>
#include <glm/glm.hpp>

#include "spectral/observer.h"
#include "spectral/spectrum.h"
#include "spectral/wavelength_fit.h"
#include "spectral/wavelength_pdf.h"

namespace prism {

using IntegrationMatrix = Eigen::Matrix<double, 3, 4>;

struct SampledWavelengths {
  std::array<double, 4> lambdaNm{};
  std::array<double, 4> pdf{};  // per nm
};

enum class SamplingStrategy { Uniform, Stratified, Rotated, Importance, Lights, Optimised };
// uniform|stratified|rotated|importance|lights|optimised
SamplingStrategy samplingStrategyFromName(std::string_view name);
std::string_view samplingStrategyName(SamplingStrategy strategy);

struct SamplingSettings {
  int count = 16;  // a multiple of 4, 4–1000
  double minNm = kLambdaMinNm;
  double maxNm = kLambdaMaxNm;
  SamplingStrategy strategy = SamplingStrategy::Uniform;
  bool operator==(const SamplingSettings&) const = default;
};

// Whether [minNm, maxNm] holds `count` whole nanometres, its ends included: what a fitted
// (optimised) set of `count` wavelengths needs, one a node of the fit's 1 nm grid. It asked for one
// more (500–503 nm was said to hold fewer than 4).
inline bool holdsWholeNanometres(double minNm, double maxNm, int count) {
  return std::floor(maxNm) - std::ceil(minNm) + 1.0 >= count;
}

// Error naming the setting when count or range is invalid (Optimised: count ≤ kMaxFittedWavelengths
// and a range that holdsWholeNanometres).
void validate(const SamplingSettings& settings);
// Its first two checks alone, for a command line to say with its option: a multiple of 4 within
// 4–1000; a range within 360–830 nm with min < max.
void validateWavelengthCount(int count);
void validateWavelengthRange(double minNm, double maxNm);

// The batches for one pixel and frame (seed unused by Uniform). `importance` is the observer
// whose response Importance follows. Not for Lights or Optimised, which need the lights (Error):
// WavelengthSampler.
std::vector<SampledWavelengths> sampleWavelengths(const SamplingSettings& settings,
                                                  std::uint32_t seed, const Observer& importance);

// The same, for callers that draw many sets (a path tracer: one per path; a renderer: one per
// frame): the settings are validated and Importance's or Lights' pdf is tabulated once, at
// construction.
class WavelengthSampler {
 public:
  // Every strategy but Lights and Optimised (Error for those).
  WavelengthSampler(const SamplingSettings& settings, const Observer& importance);
  // Every strategy but Optimised (Error); Lights follows `emission`, what the scene emits
  // (scene/scene_emission.h: its lights and background, summed), the others ignore it.
  WavelengthSampler(const SamplingSettings& settings, const Observer& importance, const Spectrum& emission);
  // Optimised: the fitted set (settings.count wavelengths, fitted for the observer the caller's
  // matrices are for).
  WavelengthSampler(const SamplingSettings& settings, FittedWavelengths fitted);
  const SamplingSettings& settings() const { return mSettings; }
  // The pdf Importance and Lights draw from; null for the other strategies.
  const WavelengthPdf* pdf() const { return mPdf ? &*mPdf : nullptr; }
  std::vector<SampledWavelengths> sample(std::uint32_t seed) const;
  // Stratified, Importance and Lights, subdivided: wavelength i lies in part `part` of `parts`
  // equal parts (in the CDF) of its stratum. Sets drawn for part = 0..parts−1, each weighted as
  // usual, average to the stratified estimate over n·parts strata (how a path tracer spreads a
  // pixel's paths over the spectrum). Uniform takes the part's midpoint; Rotated ignores parts;
  // Lights offsets the part by the seed's rotation.
  // Optimised: the fitted wavelengths whatever the seed and part (pdf 0: not a density).
  std::vector<SampledWavelengths> sample(std::uint32_t seed, int part, int parts) const;
  // Each batch's integration matrix: integrationMatrices(batches, obs), or the fitted matrix's
  // columns for Optimised.
  std::vector<IntegrationMatrix> matrices(const std::vector<SampledWavelengths>& batches, const Observer& obs) const;
  // One frame's tristimulus estimate of a spectral radiance (the frame's set for `seed`, through
  // matrices()): what a renderer's frame sums for it. For tests and reports.
  Eigen::Vector3d estimate(std::uint32_t seed, const Spectrum& radiance, const Observer& obs) const;
  // Optimised's set; null for the other strategies.
  const FittedWavelengths* fitted() const { return mFitted ? &*mFitted : nullptr; }

 private:
  SamplingSettings mSettings;
  std::optional<WavelengthPdf> mPdf;  // Importance and Lights
  std::optional<FittedWavelengths> mFitted;  // Optimised
};

// The wavelengths RGB renderers commonly stand R, G and B for (e.g. Bruneton's atmosphere,
// model.h): where an RGB mode needs a per-channel physical coefficient (water, the sky), it is
// evaluated at these.
inline constexpr std::array<float, 3> kRgbStandInWavelengthsNm{680.0f, 550.0f, 440.0f};
// As an RGB mode's batch of "wavelengths": R, G, B and a fourth channel of the caller's choice.
inline glm::vec4 rgbStandInWavelengths(float fourthNm) {
  return {kRgbStandInWavelengthsNm[0], kRgbStandInWavelengthsNm[1], kRgbStandInWavelengthsNm[2], fourthNm};
}

// M[c][j] = curve_c(λ_j) / (n·pdf_j): tristimulus += M · (L(λ_0..3)).
std::vector<IntegrationMatrix> integrationMatrices(const std::vector<SampledWavelengths>& batches,
                                                   const Observer& obs);

}  // namespace prism
