#include "techniques/atmosphere/atmosphere_reference.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <numbers>
#include <vector>

#include <glm/glm.hpp>

namespace prism::atmosphere {
namespace {

using std::numbers::pi;
constexpr int kDepthSteps = 1000;  // Simpson intervals per half of the sun's ray (even)
constexpr int kViewSteps = 1000;   // midpoint samples per piece of the view ray

struct Medium {
  const AtmosphereParameters& p;
  std::array<OpticalCoefficients, 4> c;

  Medium(const AtmosphereParameters& params, const std::array<double, 4>& lambdaNm) : p(params) {
    for (int j = 0; j < 4; ++j) c[static_cast<std::size_t>(j)] = opticalCoefficients(p, lambdaNm[static_cast<std::size_t>(j)]);
  }
  struct Density {
    double rayleigh, mie, ozone;
  };
  Density density(double r) const {
    double h = std::max(r - p.bottomRadiusKm, 0.0);
    return {std::exp(-h / p.rayleighScaleHeightKm), std::exp(-h / p.mieScaleHeightKm),
            std::max(0.0, 1.0 - std::abs(h - p.ozonePeakAltitudeKm) / p.ozoneHalfWidthKm)};
  }
  Channels extinction(double r) const {
    Density d = density(r);
    Channels e{};
    for (std::size_t j = 0; j < 4; ++j) {
      e[j] = c[j].rayleighScattering * d.rayleigh + c[j].mieExtinction * d.mie +
             c[j].ozoneAbsorption * d.ozone;
    }
    return e;
  }
};

double distanceToTop(const AtmosphereParameters& p, double r, double mu) {
  return -r * mu + std::sqrt(std::max(r * r * (mu * mu - 1.0) + p.topRadiusKm * p.topRadiusKm, 0.0));
}

bool hitsGround(const AtmosphereParameters& p, double r, double mu) {
  return mu < 0.0 && r * r * (mu * mu - 1.0) + p.bottomRadiusKm * p.bottomRadiusKm >= 0.0;
}

// Simpson over t = t0 + (t1 − t0)·s² (crowded at t0), s ∈ [0, 1].
Channels simpsonCrowded(const Medium& m, double r, double mu, double t0, double t1) {
  Channels sum{};
  for (int i = 0; i <= kDepthSteps; ++i) {
    double s = static_cast<double>(i) / kDepthSteps;
    double t = t0 + (t1 - t0) * s * s;
    double jacobian = 2.0 * s * (t1 - t0);
    double w = (i == 0 || i == kDepthSteps) ? 1.0 : (i % 2 == 1 ? 4.0 : 2.0);
    Channels e = m.extinction(std::sqrt(std::max(t * t + 2.0 * r * mu * t + r * r, 0.0)));
    for (std::size_t j = 0; j < 4; ++j) sum[j] += w * e[j] * jacobian;
  }
  for (double& v : sum) v /= 3.0 * kDepthSteps;
  return sum;
}

Channels opticalDepthToTop(const Medium& m, double r, double mu) {
  double tEnd = distanceToTop(m.p, r, mu);
  double tLowest = mu < 0.0 ? std::min(-r * mu, tEnd) : 0.0;
  Channels depth = simpsonCrowded(m, r, mu, tLowest, tEnd);
  if (tLowest > 0.0) {
    // The first half, crowded at its end: t = tLowest − tLowest·s².
    Channels first{};
    for (int i = 0; i <= kDepthSteps; ++i) {
      double s = static_cast<double>(i) / kDepthSteps;
      double t = tLowest - tLowest * s * s;
      double jacobian = 2.0 * s * tLowest;
      double w = (i == 0 || i == kDepthSteps) ? 1.0 : (i % 2 == 1 ? 4.0 : 2.0);
      Channels e = m.extinction(std::sqrt(std::max(t * t + 2.0 * r * mu * t + r * r, 0.0)));
      for (std::size_t j = 0; j < 4; ++j) first[j] += w * e[j] * jacobian;
    }
    for (std::size_t j = 0; j < 4; ++j) depth[j] += first[j] / (3.0 * kDepthSteps);
  }
  return depth;
}

}  // namespace

Channels referenceOpticalDepth(const AtmosphereParameters& p, const std::array<double, 4>& lambdaNm,
                               double rKm, double mu) {
  return opticalDepthToTop(Medium(p, lambdaNm), rKm, mu);
}

Channels referenceSingleScattering(const AtmosphereParameters& p,
                                   const std::array<double, 4>& lambdaNm, double rKm,
                                   double muSun, double zenith, double azimuth) {
  return referenceSingleScatteringTo(p, lambdaNm, rKm, muSun, zenith, azimuth,
                                     std::numeric_limits<double>::infinity())
      .radiance;
}

ReferenceSegment referenceSingleScatteringTo(const AtmosphereParameters& p,
                                             const std::array<double, 4>& lambdaNm, double rKm,
                                             double muSun, double zenith, double azimuth,
                                             double maxDistanceKm) {
  Medium m(p, lambdaNm);
  const glm::dvec3 origin(0.0, rKm, 0.0);
  const glm::dvec3 sun(std::sqrt(std::max(1.0 - muSun * muSun, 0.0)), muSun, 0.0);
  const glm::dvec3 dir(std::sin(zenith) * std::cos(azimuth), std::cos(zenith),
                       std::sin(zenith) * std::sin(azimuth));
  double mu = dir.y;
  double tMax = hitsGround(p, rKm, mu)
                    ? -rKm * mu - std::sqrt(std::max(rKm * rKm * (mu * mu - 1.0) +
                                                         p.bottomRadiusKm * p.bottomRadiusKm, 0.0))
                    : distanceToTop(p, rKm, mu);
  tMax = std::min(tMax, maxDistanceKm);
  auto shadowed = [&](double t) {
    glm::dvec3 x = origin + dir * t;
    double r = glm::length(x);
    return hitsGround(p, r, glm::dot(x, sun) / r);
  };
  // Break points: the lowest point, and every change of shadowed along a fine scan (bisected).
  std::vector<double> breaks{0.0, tMax};
  double tLow = std::clamp(-glm::dot(origin, dir), 0.0, tMax);
  if (tLow > 0.0 && tLow < tMax) breaks.push_back(tLow);
  const int scan = 4096;
  for (int i = 0; i < scan; ++i) {
    double a = tMax * i / scan, b = tMax * (i + 1) / scan;
    if (shadowed(a) == shadowed(b)) continue;
    for (int k = 0; k < 60; ++k) {
      double mid = 0.5 * (a + b);
      (shadowed(mid) == shadowed(a) ? a : b) = mid;
    }
    breaks.push_back(0.5 * (a + b));
  }
  std::sort(breaks.begin(), breaks.end());

  const double nu = glm::dot(dir, sun);
  const double g = p.miePhaseG;
  const double phaseR = 3.0 / (16.0 * pi) * (1.0 + nu * nu);
  const double phaseM = 3.0 / (8.0 * pi) * (1.0 - g * g) / (2.0 + g * g) * (1.0 + nu * nu) /
                        std::pow(1.0 + g * g - 2.0 * g * nu, 1.5);
  Channels radiance{}, depth{};
  for (std::size_t piece = 0; piece + 1 < breaks.size(); ++piece) {
    double t0 = breaks[piece], t1 = breaks[piece + 1];
    if (t1 <= t0) continue;
    bool towardsStart = t0 >= tLow;  // crowd at the end nearer the lowest point
    bool lit = !shadowed(0.5 * (t0 + t1));
    for (int k = 0; k < kViewSteps; ++k) {
      int i = towardsStart ? k : kViewSteps - 1 - k;
      double s0 = static_cast<double>(i) / kViewSteps, s1 = static_cast<double>(i + 1) / kViewSteps;
      double um = 0.5 * (s0 * s0 + s1 * s1), dt = (s1 * s1 - s0 * s0) * (t1 - t0);
      double t = towardsStart ? t0 + um * (t1 - t0) : t1 - um * (t1 - t0);
      glm::dvec3 x = origin + dir * t;
      double r = glm::length(x);
      Channels e = m.extinction(r);
      if (lit) {
        Medium::Density d = m.density(r);
        Channels sunDepth = opticalDepthToTop(m, r, glm::dot(x, sun) / r);
        for (std::size_t j = 0; j < 4; ++j) {
          double viewT = std::exp(-(depth[j] + 0.5 * e[j] * dt));
          double scattering = m.c[j].rayleighScattering * d.rayleigh * phaseR +
                              m.c[j].mieScattering * d.mie * phaseM;
          radiance[j] += viewT * std::exp(-sunDepth[j]) * scattering * m.c[j].solarIrradiance * dt;
        }
      }
      for (std::size_t j = 0; j < 4; ++j) depth[j] += e[j] * dt;
    }
  }
  ReferenceSegment segment;
  segment.radiance = radiance;
  for (std::size_t j = 0; j < 4; ++j) segment.transmittance[j] = std::exp(-depth[j]);
  return segment;
}

}  // namespace prism::atmosphere
