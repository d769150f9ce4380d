#include "spectral/sampling.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <string>
#include <utility>

#include "shared_cpp.h"
#include "core/error.h"

namespace prism::shared {
#include "random.glsl"
}

namespace prism {

SamplingStrategy samplingStrategyFromName(std::string_view name) {
  if (name == "uniform") return SamplingStrategy::Uniform;
  if (name == "stratified") return SamplingStrategy::Stratified;
  if (name == "rotated") return SamplingStrategy::Rotated;
  if (name == "importance") return SamplingStrategy::Importance;
  if (name == "lights") return SamplingStrategy::Lights;
  if (name == "optimised") return SamplingStrategy::Optimised;
  throw Error("unknown sampling strategy '" + std::string(name) +
              "' (known: uniform, stratified, rotated, importance, lights, optimised)");
}

std::string_view samplingStrategyName(SamplingStrategy strategy) {
  switch (strategy) {
    case SamplingStrategy::Uniform: return "uniform";
    case SamplingStrategy::Stratified: return "stratified";
    case SamplingStrategy::Rotated: return "rotated";
    case SamplingStrategy::Importance: return "importance";
    case SamplingStrategy::Lights: return "lights";
    case SamplingStrategy::Optimised: return "optimised";
  }
  return "?";
}

void validateWavelengthCount(int count) {
  if (count < 4 || count > 1000 || count % 4 != 0)
    throw Error("wavelength count must be a multiple of 4 within 4–1000, got " + std::to_string(count));
}

void validateWavelengthRange(double minNm, double maxNm) {
  if (!(minNm >= kLambdaMinNm && maxNm <= kLambdaMaxNm && minNm < maxNm)) {
    std::ostringstream range;  // as given: 500, not 500.000000
    range << minNm << "–" << maxNm;
    throw Error("wavelength range must lie within 360–830 nm with min < max, got " + range.str() + " nm");
  }
}

void validate(const SamplingSettings& s) {
  validateWavelengthCount(s.count);
  validateWavelengthRange(s.minNm, s.maxNm);
  if (s.strategy == SamplingStrategy::Optimised && s.count > kMaxFittedWavelengths)
    throw Error("the optimised strategy fits 4–" + std::to_string(kMaxFittedWavelengths) + " wavelengths, got " +
                std::to_string(s.count) + " (uniform, rotated or lights take more)");
  if (s.strategy == SamplingStrategy::Optimised && !holdsWholeNanometres(s.minNm, s.maxNm, s.count)) {
    std::ostringstream range;
    range << s.minNm << "–" << s.maxNm;
    const double held = std::max(0.0, std::floor(s.maxNm) - std::ceil(s.minNm) + 1.0);
    throw Error("the optimised strategy fits its " + std::to_string(s.count) + " wavelengths on whole nanometres: " +
                range.str() + " nm holds " + std::to_string(static_cast<int>(held)));
  }
}

WavelengthSampler::WavelengthSampler(const SamplingSettings& settings, const Observer& importance)
    : mSettings(settings) {
  // Lights needs the lights' emission, Optimised its fitted set: a library caller's choice, said as
  // an Error (it aborted on an internal check).
  if (settings.strategy == SamplingStrategy::Lights || settings.strategy == SamplingStrategy::Optimised)
    throw Error("the " + std::string(samplingStrategyName(settings.strategy)) + " strategy needs " +
                (settings.strategy == SamplingStrategy::Lights ? "the lights' emission" : "its fitted set") +
                ": construct a WavelengthSampler with it");
  validate(settings);
  if (settings.strategy == SamplingStrategy::Importance) {
    mPdf = WavelengthPdf::observerResponse(importance, settings.minNm, settings.maxNm);
  }
}

WavelengthSampler::WavelengthSampler(const SamplingSettings& settings, const Observer& importance,
                                     const Spectrum& emission)
    : mSettings(settings) {
  if (settings.strategy == SamplingStrategy::Optimised)
    throw Error("the optimised strategy needs its fitted set: construct a WavelengthSampler with it");
  validate(settings);
  if (settings.strategy == SamplingStrategy::Importance) {
    mPdf = WavelengthPdf::observerResponse(importance, settings.minNm, settings.maxNm);
  } else if (settings.strategy == SamplingStrategy::Lights) {
    mPdf = WavelengthPdf::lightsAndObserver(emission, importance, settings.minNm, settings.maxNm);
  }
}

WavelengthSampler::WavelengthSampler(const SamplingSettings& settings, FittedWavelengths fitted)
    : mSettings(settings), mFitted(std::move(fitted)) {
  PRISM_CHECK(settings.strategy == SamplingStrategy::Optimised);
  validate(settings);
  PRISM_CHECK(mFitted->lambdaNm.size() == static_cast<std::size_t>(settings.count) &&
              mFitted->weights.cols() == settings.count);
}

std::vector<SampledWavelengths> sampleWavelengths(const SamplingSettings& settings,
                                                  std::uint32_t seed, const Observer& importance) {
  return WavelengthSampler(settings, importance).sample(seed);
}

std::vector<SampledWavelengths> WavelengthSampler::sample(std::uint32_t seed) const {
  return sample(seed, 0, 1);
}

std::vector<SampledWavelengths> WavelengthSampler::sample(std::uint32_t seed, int part,
                                                          int parts) const {
  PRISM_CHECK(parts >= 1 && part >= 0 && part < parts);
  const SamplingSettings& s = mSettings;
  const int n = s.count;
  const double width = s.maxNm - s.minNm;
  std::vector<SampledWavelengths> batches(static_cast<std::size_t>(n / 4));
  auto set = [&](int i, double lambdaNm, double pdf) {
    batches[static_cast<std::size_t>(i / 4)].lambdaNm[static_cast<std::size_t>(i % 4)] = lambdaNm;
    batches[static_cast<std::size_t>(i / 4)].pdf[static_cast<std::size_t>(i % 4)] = pdf;
  };
  // The golden-ratio sequence: successive seeds' offsets fill [0, 1) evenly.
  constexpr double kGoldenRatioConjugate = 0.6180339887498949;
  const double rotation = std::fmod(0.5 + static_cast<double>(seed) * kGoldenRatioConjugate, 1.0);
  auto jitter = [&](int i) {
    return static_cast<double>(shared::randomFloat(seed, static_cast<std::uint32_t>(i)));
  };
  if (mFitted) {
    for (int i = 0; i < n; ++i) set(i, mFitted->lambdaNm[static_cast<std::size_t>(i)], 0.0);
    return batches;
  }
  if (mPdf) {
    for (int i = 0; i < n; ++i) {
      double offset = s.strategy == SamplingStrategy::Lights ? rotation : jitter(i);
      WavelengthPdf::Sample w = mPdf->invert((i + (part + offset) / parts) / n);
      set(i, w.lambdaNm, w.pdf);
    }
    return batches;
  }
  for (int i = 0; i < n; ++i) {
    double offset = s.strategy == SamplingStrategy::Uniform   ? (part + 0.5) / parts
                    : s.strategy == SamplingStrategy::Rotated ? rotation
                                                              : (part + jitter(i)) / parts;
    set(i, s.minNm + (i + offset) * width / n, 1.0 / width);
  }
  return batches;
}

std::vector<IntegrationMatrix> integrationMatrices(const std::vector<SampledWavelengths>& batches,
                                                   const Observer& obs) {
  const double n = 4.0 * static_cast<double>(batches.size());
  std::vector<IntegrationMatrix> matrices;
  for (const SampledWavelengths& b : batches) {
    IntegrationMatrix m;
    for (int j = 0; j < 4; ++j)
      m.col(j) = obs.at(b.lambdaNm[static_cast<std::size_t>(j)]) / (n * b.pdf[static_cast<std::size_t>(j)]);
    matrices.push_back(m);
  }
  return matrices;
}

std::vector<IntegrationMatrix> WavelengthSampler::matrices(const std::vector<SampledWavelengths>& batches,
                                                         const Observer& obs) const {
  if (!mFitted) return integrationMatrices(batches, obs);
  PRISM_CHECK(batches.size() * 4 == static_cast<std::size_t>(mFitted->weights.cols()));
  std::vector<IntegrationMatrix> out;
  for (std::size_t b = 0; b < batches.size(); ++b)
    out.push_back(mFitted->weights.middleCols(static_cast<Eigen::Index>(4 * b), 4));
  return out;
}

Eigen::Vector3d WavelengthSampler::estimate(std::uint32_t seed, const Spectrum& radiance, const Observer& obs) const {
  const std::vector<SampledWavelengths> batches = sample(seed);
  const std::vector<IntegrationMatrix> m = matrices(batches, obs);
  Eigen::Vector3d xyz = Eigen::Vector3d::Zero();
  for (std::size_t b = 0; b < batches.size(); ++b) {
    Eigen::Vector4d l;
    for (int j = 0; j < 4; ++j) l[j] = radiance.at(batches[b].lambdaNm[static_cast<std::size_t>(j)]);
    xyz += m[b] * l;
  }
  return xyz;
}

}  // namespace prism
