#include "spectral/sampling.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "shared_cpp.h"
#include "core/error.h"

namespace prism::shared {
#include "random.glsl"
}

namespace prism {

// Piecewise-constant pdf over 1 nm bins of [minNm, maxNm] (the last bin may be shorter),
// proportional to the observer's summed response.
struct WavelengthSampler::ResponsePdf {
  std::vector<double> edgesNm;  // bins + 1
  std::vector<double> density;  // per nm, integrates to 1
  std::vector<double> cdf;      // at edges

  ResponsePdf(const Observer& obs, double minNm, double maxNm) {
    for (double e = minNm; e < maxNm; e += 1.0) edgesNm.push_back(e);
    edgesNm.push_back(maxNm);
    std::vector<double> value;
    double mean = 0.0;
    for (std::size_t i = 0; i + 1 < edgesNm.size(); ++i) {
      double mid = 0.5 * (edgesNm[i] + edgesNm[i + 1]);
      value.push_back(obs.at(mid).sum());
      mean += value.back();
    }
    mean /= static_cast<double>(value.size());
    double floor = 1e-3 * mean;
    cdf.push_back(0.0);
    for (std::size_t i = 0; i < value.size(); ++i) {
      value[i] = std::max(value[i], floor);
      cdf.push_back(cdf.back() + value[i] * (edgesNm[i + 1] - edgesNm[i]));
    }
    double total = cdf.back();
    for (double& c : cdf) c /= total;
    for (double& v : value) v /= total;
    density = std::move(value);
  }

  // λ with CDF(λ) = u, and its pdf.
  std::pair<double, double> invert(double u) const {
    auto it = std::upper_bound(cdf.begin(), cdf.end(), u);
    std::size_t bin = std::min(static_cast<std::size_t>(std::max<std::ptrdiff_t>(it - cdf.begin() - 1, 0)),
                               density.size() - 1);
    double width = edgesNm[bin + 1] - edgesNm[bin];
    double t = (u - cdf[bin]) / (density[bin] * width);
    double lambda = edgesNm[bin] + std::clamp(t, 0.0, 1.0) * width;
    return {lambda, density[bin]};
  }
};


SamplingStrategy samplingStrategyFromName(std::string_view name) {
  if (name == "uniform") return SamplingStrategy::Uniform;
  if (name == "stratified") return SamplingStrategy::Stratified;
  if (name == "rotated") return SamplingStrategy::Rotated;
  if (name == "importance") return SamplingStrategy::Importance;
  throw Error("unknown sampling strategy '" + std::string(name) +
              "' (known: uniform, stratified, rotated, importance)");
}

std::string_view samplingStrategyName(SamplingStrategy strategy) {
  switch (strategy) {
    case SamplingStrategy::Uniform: return "uniform";
    case SamplingStrategy::Stratified: return "stratified";
    case SamplingStrategy::Rotated: return "rotated";
    case SamplingStrategy::Importance: return "importance";
  }
  return "?";
}

void validate(const SamplingSettings& s) {
  if (s.count < 4 || s.count > 1000 || s.count % 4 != 0)
    throw Error("wavelength count must be a multiple of 4 within 4–1000, got " +
                std::to_string(s.count));
  if (!(s.minNm >= kLambdaMinNm && s.maxNm <= kLambdaMaxNm && s.minNm < s.maxNm))
    throw Error("wavelength range must lie within 360–830 nm with min < max, got " +
                std::to_string(s.minNm) + "–" + std::to_string(s.maxNm) + " nm");
}

WavelengthSampler::WavelengthSampler(const SamplingSettings& settings, const Observer& importance)
    : mSettings(settings) {
  validate(settings);
  if (settings.strategy == SamplingStrategy::Importance) {
    mPdf = std::make_unique<ResponsePdf>(importance, settings.minNm, settings.maxNm);
  }
}

WavelengthSampler::~WavelengthSampler() = default;
WavelengthSampler::WavelengthSampler(WavelengthSampler&&) noexcept = default;
WavelengthSampler& WavelengthSampler::operator=(WavelengthSampler&&) noexcept = default;

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
  if (s.strategy == SamplingStrategy::Importance) {
    const ResponsePdf& pdf = *mPdf;
    for (int i = 0; i < n; ++i) {
      double jitter = static_cast<double>(shared::randomFloat(seed, static_cast<std::uint32_t>(i)));
      double u = (i + (part + jitter) / parts) / n;
      auto [lambda, p] = pdf.invert(u);
      batches[static_cast<std::size_t>(i / 4)].lambdaNm[static_cast<std::size_t>(i % 4)] = lambda;
      batches[static_cast<std::size_t>(i / 4)].pdf[static_cast<std::size_t>(i % 4)] = p;
    }
    return batches;
  }
  constexpr double kGoldenRatioConjugate = 0.6180339887498949;
  const double rotation = std::fmod(0.5 + static_cast<double>(seed) * kGoldenRatioConjugate, 1.0);
  for (int i = 0; i < n; ++i) {
    double offset = s.strategy == SamplingStrategy::Uniform   ? (part + 0.5) / parts
                    : s.strategy == SamplingStrategy::Rotated ? rotation
                    : (part + static_cast<double>(shared::randomFloat(seed, static_cast<std::uint32_t>(i)))) / parts;
    batches[static_cast<std::size_t>(i / 4)].lambdaNm[static_cast<std::size_t>(i % 4)] =
        s.minNm + (i + offset) * width / n;
    batches[static_cast<std::size_t>(i / 4)].pdf[static_cast<std::size_t>(i % 4)] = 1.0 / width;
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

}  // namespace prism
