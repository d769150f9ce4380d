#include "techniques/atmosphere/sky_evaluation.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <numbers>

#include "spectral/colour_difference.h"
#include "core/parallel_for.h"
#include "techniques/atmosphere/atmosphere_tables.h"

namespace prism::atmosphere {
namespace {

using std::numbers::pi;

// Runs every batch of the strategy over every sample; body(batch, sample, radiance).
void forEachBatchSample(const AtmosphereParameters& p, const SkyStrategy& strategy,
                        const SkySamples& samples, const Progress& progress,
                        const std::function<void(std::size_t, std::size_t, const glm::vec4&)>& body) {
  const float r = static_cast<float>(p.bottomRadiusKm + samples.cameraAltitudeKm);
  std::size_t done = 0, total = strategy.batches.size();
  for (std::size_t b = 0; b < strategy.batches.size(); ++b) {
    const SkyBatch& batch = strategy.batches[b];
    AtmosphereTables tables = computeTables(packAtmosphere(p, batch.lambdaNm, batch.solarIrradiance));
    parallelFor(samples.sunElevationsDeg.size(), 0, [&](std::size_t e) {
      float muSun = static_cast<float>(std::sin(samples.sunElevationsDeg[e] * pi / 180.0));
      for (std::size_t d = 0; d < samples.zenith.size(); ++d) {
        glm::vec4 radiance = skyRadiance(tables, r, muSun, static_cast<float>(samples.zenith[d]),
                                         static_cast<float>(samples.azimuth[d]), false);
        body(b, samples.index(e, d), radiance);
      }
    });
    if (progress) progress(++done, total);
  }
}

}  // namespace

SkySamples makeSkySamples(std::vector<double> sunElevationsDeg, int zeniths, int azimuths) {
  SkySamples s;
  s.sunElevationsDeg = std::move(sunElevationsDeg);
  for (int i = 0; i < zeniths; ++i) {
    double cosZenith = (i + 0.5) / zeniths;
    for (int j = 0; j < azimuths; ++j) {
      s.zenith.push_back(std::acos(cosZenith));
      s.azimuth.push_back((j + 0.5) / azimuths * pi);
    }
  }
  return s;
}

std::vector<Eigen::Vector3d> skyTristimulus(const AtmosphereParameters& p, const SkyStrategy& strategy,
                                            const SkySamples& samples, const Progress& progress) {
  std::vector<Eigen::Vector3d> xyz(samples.size(), Eigen::Vector3d::Zero());
  forEachBatchSample(p, strategy, samples, progress, [&](std::size_t b, std::size_t i, const glm::vec4& L) {
    Eigen::Vector4d l(L.x, L.y, L.z, L.w);
    xyz[i] += strategy.batches[b].toXyz * l;
  });
  return xyz;
}

double SpectralSky::at(std::size_t sample, double lambda) const {
  const std::size_t n = lambdaNm.size();
  double step = (lambdaNm.back() - lambdaNm.front()) / double(n - 1);
  double f = std::clamp((lambda - lambdaNm.front()) / step, 0.0, double(n - 1));
  std::size_t i = std::min(static_cast<std::size_t>(f), n - 2);
  double t = f - double(i);
  const float* row = radiance.data() + sample * n;
  return row[i] * (1.0 - t) + row[i + 1] * t;
}

SpectralSky spectralSky(const AtmosphereParameters& p, double stepNm, const SkySamples& samples,
                        const Progress& progress) {
  SkyStrategy reference = referenceStrategy(stepNm);
  SpectralSky s;
  for (const SkyBatch& b : reference.batches) {
    for (int j = 0; j < 4; ++j) {
      if (b.lambdaNm[j] > 0.0f) s.lambdaNm.push_back(b.lambdaNm[j]);
    }
  }
  const std::size_t n = s.lambdaNm.size();
  s.radiance.assign(samples.size() * n, 0.0f);
  s.xyz.assign(samples.size(), Eigen::Vector3d::Zero());
  std::vector<Eigen::Vector3d>& xyz = s.xyz;
  forEachBatchSample(p, reference, samples, progress, [&](std::size_t b, std::size_t i, const glm::vec4& L) {
    for (std::size_t j = 0; j < 4 && b * 4 + j < n; ++j) s.radiance[i * n + b * 4 + j] = L[static_cast<int>(j)];
    xyz[i] += reference.batches[b].toXyz * Eigen::Vector4d(L.x, L.y, L.z, L.w);
  });
  return s;
}

std::vector<double> exposures(const SkySamples& samples, const std::vector<Eigen::Vector3d>& reference) {
  std::vector<double> k;
  for (std::size_t e = 0; e < samples.sunElevationsDeg.size(); ++e) {
    double meanY = 0.0;
    for (std::size_t d = 0; d < samples.zenith.size(); ++d) meanY += reference[samples.index(e, d)].y();
    meanY /= double(samples.zenith.size());
    k.push_back(meanY > 0.0 ? 0.18 / meanY : 0.0);
  }
  return k;
}

Eigen::Vector3d exposedLab(const Eigen::Vector3d& xyz, double exposure) {
  static const Eigen::Vector3d d65(0.95047, 1.0, 1.08883);  // CIE D65, 2°
  return xyzToLab(xyz * exposure, d65);
}

std::vector<ElevationError> compareSkies(const SkySamples& samples, const std::vector<Eigen::Vector3d>& test,
                                         const std::vector<Eigen::Vector3d>& reference) {
  std::vector<double> k = exposures(samples, reference);
  std::vector<ElevationError> out;
  for (std::size_t e = 0; e < samples.sunElevationsDeg.size(); ++e) {
    ElevationError err;
    err.elevationDeg = samples.sunElevationsDeg[e];
    for (std::size_t d = 0; d < samples.zenith.size(); ++d) {
      std::size_t i = samples.index(e, d);
      double de = deltaE(exposedLab(test[i], k[e]), exposedLab(reference[i], k[e]));
      err.meanDeltaE += de;
      err.maxDeltaE = std::max(err.maxDeltaE, de);
    }
    err.meanDeltaE /= double(samples.zenith.size());
    out.push_back(err);
  }
  return out;
}

}  // namespace prism::atmosphere
