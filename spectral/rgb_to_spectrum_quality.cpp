#include "spectral/rgb_to_spectrum_quality.h"

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include "shared_cpp.h"
#include "spectral/colour_difference.h"
#include "spectral/colour_space.h"
#include "spectral/observer.h"
#include "core/parallel_for.h"
#include "spectral/sigmoid_fit.h"

namespace prism::shared {
#include "sigmoid.glsl"
}

namespace prism {
namespace {

// ΔE00 of each colour and the extremes of each spectrum, then the summary.
struct Sample {
  double deltaE = 0.0;
  double minReflectance = 0.0;
  double maxReflectance = 0.0;
};

class Colourimeter {
 public:
  explicit Colourimeter(const RgbColourSpace& gamut)
      : mGamut(gamut), mWeights(reflectanceWeights(observer("cie1931"), gamutWhiteIlluminant(gamut))) {
    mWhite = Eigen::Vector3d::Zero();
    for (const Eigen::Vector3d& w : mWeights) mWhite += w;
  }

  Sample measure(const glm::vec3& targetRgb, const glm::vec3& coeffs) const {
    Sample s{0.0, 1.0, 0.0};
    Eigen::Vector3d xyz = Eigen::Vector3d::Zero();
    for (int i = 0; i < kSpectrumSamples; ++i) {
      double f = shared::upsampledReflectance(coeffs, static_cast<float>(kLambdaMinNm + i));
      xyz += mWeights[static_cast<std::size_t>(i)] * f;
      s.minReflectance = std::min(s.minReflectance, f);
      s.maxReflectance = std::max(s.maxReflectance, f);
    }
    Eigen::Vector3d target = mGamut.rgbToXyz * Eigen::Vector3d(targetRgb.x, targetRgb.y, targetRgb.z);
    s.deltaE = deltaE(xyzToLab(xyz, mWhite), xyzToLab(target, mWhite));
    return s;
  }

 private:
  const RgbColourSpace& mGamut;
  std::vector<Eigen::Vector3d> mWeights;
  Eigen::Vector3d mWhite;
};

UpsamplingError summarise(const std::vector<Sample>& samples, const std::vector<glm::vec3>& rgbs) {
  UpsamplingError e;
  e.count = samples.size();
  double sumSq = 0.0;
  std::size_t within = 0;
  for (std::size_t i = 0; i < samples.size(); ++i) {
    const Sample& s = samples[i];
    sumSq += s.deltaE * s.deltaE;
    within += s.deltaE <= 1.0;
    if (s.deltaE > e.maxDeltaE2000 || i == 0) {
      e.maxDeltaE2000 = s.deltaE;
      e.worstRgb = rgbs[i];
    }
    e.minReflectance = std::min(e.minReflectance, s.minReflectance);
    e.maxReflectance = std::max(e.maxReflectance, s.maxReflectance);
  }
  e.rmsDeltaE2000 = std::sqrt(sumSq / static_cast<double>(samples.size()));
  e.fractionWithin1 = static_cast<double>(within) / static_cast<double>(samples.size());
  return e;
}

}  // namespace

UpsamplingError nodeError(const RgbToSpectrumTable& table, unsigned threads) {
  const Colourimeter meter(colourSpace(table.gamut()));
  const int res = table.resolution();
  const std::size_t count = 3 * static_cast<std::size_t>(res) * static_cast<std::size_t>(res) *
                            static_cast<std::size_t>(res);
  std::vector<Sample> samples(count);
  std::vector<glm::vec3> rgbs(count);
  parallelFor(count, threads, [&](std::size_t n) {
    int xi = static_cast<int>(n % static_cast<std::size_t>(res));
    int yi = static_cast<int>(n / static_cast<std::size_t>(res) % static_cast<std::size_t>(res));
    int zi = static_cast<int>(n / static_cast<std::size_t>(res * res) % static_cast<std::size_t>(res));
    int block = static_cast<int>(n / static_cast<std::size_t>(res * res * res));
    rgbs[n] = table.nodeRgb(block, zi, yi, xi);
    samples[n] = meter.measure(rgbs[n], table.coefficients(block, zi, yi, xi));
  });
  return summarise(samples, rgbs);
}

UpsamplingError lookupError(const RgbToSpectrumTable& table, LookupPath path,
                            std::span<const glm::vec3> rgbs, unsigned threads) {
  const Colourimeter meter(colourSpace(table.gamut()));
  std::vector<Sample> results(rgbs.size());
  parallelFor(rgbs.size(), threads, [&](std::size_t i) {
    glm::vec3 coeffs = path == LookupPath::Manual     ? table.lookup(rgbs[i])
                       : path == LookupPath::Filtered ? table.lookupFiltered(rgbs[i])
                                                      : table.lookupFiltered(rgbs[i], 8);
    results[i] = meter.measure(rgbs[i], coeffs);
  });
  return summarise(results, std::vector<glm::vec3>(rgbs.begin(), rgbs.end()));
}

UpsamplingError roundTripError(const RgbToSpectrumTable& table, LookupPath path,
                               std::size_t samples, std::uint32_t seed, unsigned threads) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> unit(0.0f, 1.0f);
  std::vector<glm::vec3> rgbs(samples);
  for (glm::vec3& c : rgbs) c = glm::vec3(unit(rng), unit(rng), unit(rng));
  return lookupError(table, path, rgbs, threads);
}

}  // namespace prism
