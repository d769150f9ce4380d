#include "techniques/nebula/nebula_basis_coverage.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <utility>
#include <vector>

#include <fmt/format.h>

#include "techniques/nebula/nebula_integrals.h"
#include "techniques/nebula/nebula_precomputed.h"

namespace prism::nebula {

BasisCoverage basisCoverage(const NebulaRenderer& renderer, const RenderSettings& s, const NebulaCamera& cam, int rays) {
  BasisCoverage coverage;
  const bool projection = s.method == Method::Projection;
  const NebulaPrecomputed& pre = renderer.precomputed();
  const NebulaModel& m = pre.model;
  const NebulaViewFrame frame = viewFrame(cam);
  const double tanHalf = std::tan(cam.fovYDeg * std::numbers::pi / 360.0);
  const double aspect = static_cast<double>(cam.width) / cam.height;
  const int across = std::min(rays, cam.width), down = std::min(rays, cam.height);
  const double family = s.basisMaxDepthUm;
  std::vector<double> total, beyond, depth;  // per ray
  std::vector<std::pair<double, double>> samples;  // a ray's (x, star light)
  for (int row = 0; row < down; ++row)
    for (int col = 0; col < across; ++col) {
      const double px = (col + 0.5) * cam.width / across, py = (row + 0.5) * cam.height / down;
      const double u = (2.0 * px / cam.width - 1.0) * tanHalf * aspect, v = (1.0 - 2.0 * py / cam.height) * tanHalf;
      const glm::dvec3 dir = glm::normalize(frame.forward + u * frame.right + v * frame.up);
      double t0 = 0.0, t1 = 0.0, light = 0.0, far = 0.0;
      samples.clear();
      ++coverage.rays;
      if (shared::f64::nebulaClipToCube(cam.position, dir, 1e30, t0, t1)) {
        ++coverage.raysMeetingCube;
        const double dt = (t1 - t0) / s.steps;
        double gCam = 0.0;
        for (int i = 0; i < s.steps && !shared::f64::nebulaRayOpaque(gCam); ++i) {
          const glm::dvec3 p = cam.position + dir * (t0 + (i + 0.5) * dt);
          const double rho = m.density.sample(p);
          if (rho <= 0.0) continue;
          const double dg = kCtUm * m.extinction * rho * dt, g = gCam + 0.5 * dg;
          if (gCam < 5.0 * kBandLoUm) coverage.thickestStep = std::max(coverage.thickestStep, dg / kBandLoUm);
          gCam += dg;
          if (!projection) continue;
          for (std::size_t st = 0; st < m.stars.size(); ++st) {
            float gs = 0.0f;
            pre.starDepth[st].sample(p, &gs);
            const glm::dvec3 toStar = m.stars[st].position - p;
            const double x = g + gs;
            const double w = shared::f64::nebulaStarWeight(m.scattering * rho * dt, m.stars[st].luminosity, glm::dot(toStar, toStar)) *
                             shared::f64::nebulaExpMoments(x, glm::dvec4(0.0), kBandLoUm, kBandHiUm).x;
            if (w <= 0.0) continue;
            light += w;
            samples.emplace_back(x, w);
            if (x > family) far += w;
          }
        }
      }
      // The depth within which 99 % of the ray's star light arrives.
      std::sort(samples.begin(), samples.end());
      double within = 0.0, at = 0.0;
      for (const auto& [x, w] : samples) {
        at = x;
        if ((within += w) >= 0.99 * light) break;
      }
      total.push_back(light), beyond.push_back(far), depth.push_back(at);
    }
  const double brightest = total.empty() ? 0.0 : *std::max_element(total.begin(), total.end());
  for (std::size_t r = 0; r < total.size(); ++r)
    if (brightest > 0.0 && total[r] >= 0.01 * brightest) {
      coverage.worstShare = std::max(coverage.worstShare, beyond[r] / total[r]);
      coverage.lightDepthUm = std::max(coverage.lightDepthUm, depth[r]);
    }
  return coverage;
}

std::string outOfViewWarning(const BasisCoverage& coverage) {
  if (coverage.rays == 0 || coverage.raysMeetingCube > 0) return "";
  return fmt::format("the camera looks away from the nebula, so its image is black: none of {} rays spread over the "
                     "image meets the nebula's cube (see the camera's position and target)",
                     coverage.rays);
}

namespace {

// `v` rounded up at three significant figures: a depth just past the basis's, rounded to nearest,
// was printed as the basis's own ("99 % of it within 2 µm, the basis 2 µm").
double upAtThreeFigures(double v) {
  if (!(v > 0.0)) return v;
  const double unit = std::pow(10.0, std::floor(std::log10(v)) - 2.0);
  return std::ceil(v / unit - 1e-9) * unit;
}

}  // namespace

std::string basisCoverageWarning(const BasisCoverage& coverage, const RenderSettings& s, std::string_view deeperBasisFormat) {
  if (coverage.worstShare <= 0.01) return "";
  const double depth = std::ceil(coverage.lightDepthUm);
  const std::string remedy = depth <= kMaxBasisDepthUm
                                 ? fmt::format(fmt::runtime(deeperBasisFormat), depth) + " fits deeper, method analytic integrates exactly"
                                 : fmt::format("no basis is fitted deeper than {:g} µm: method analytic integrates exactly", kMaxBasisDepthUm);
  return fmt::format("up to {:.3g} % of a pixel's star light reaches the camera through more dust than the basis is "
                     "fitted for (99 % of it within an optical depth of {:.3g} µm, the basis {:g} µm): the {} method's "
                     "error there can exceed 2 % by far; {}",
                     100.0 * coverage.worstShare, upAtThreeFigures(coverage.lightDepthUm), s.basisMaxDepthUm,
                     methodName(s.method), remedy);
}

std::string stepThicknessWarning(const BasisCoverage& coverage, const RenderSettings& s, std::string_view moreStepsFormat) {
  constexpr double kThickest = 0.5;
  const double tau = coverage.thickestStep;
  if (tau <= kThickest) return "";
  const double kept = std::exp(-0.5 * tau) * tau / -std::expm1(-tau);  // the midpoint's share of the step's light
  const double steps = std::ceil(s.steps * tau / kThickest);
  const std::string remedy =
      steps <= kMaxSteps ? fmt::format(fmt::runtime(moreStepsFormat), steps) + " keeps every step within 0.5"
                         : fmt::format("even {} steps leave them {:.2g} thick: the cloud is too dense for the march", kMaxSteps,
                                       tau * s.steps / kMaxSteps);
  return fmt::format("the march's steps are up to {:.3g} optical depths thick at 380 nm, where such a step's emission "
                     "and scattered light come out {:.3g} % too dark (each is taken at the step's middle); {}",
                     tau, 100.0 * (1.0 - kept), remedy);
}

}  // namespace prism::nebula
