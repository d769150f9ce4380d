#include "techniques/prt/metamer.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include <Eigen/QR>
#include <fmt/format.h>
#include <nlopt.hpp>

#include "core/error.h"
#include "spectral/colour_difference.h"
#include "techniques/prt/prt_spectra.h"

namespace prism::prt {
namespace {

// The 1 nm node's share of each grid value when a grid function is extended piecewise linearly
// (constant beyond 380 and 780 nm).
void gridShares(int node, int& k0, int& k1, double& w1) {
  double lambda = kLambdaMinNm + node;
  double t = std::clamp((lambda - kGridMinNm) / kGridStepNm, 0.0, kGridWavelengths - 1.0);
  k0 = std::min(static_cast<int>(t), kGridWavelengths - 2);
  k1 = k0 + 1;
  w1 = t - k0;
}

// W (3 × 81): the colour under an illuminant (white Y = 1) of a grid function, exactly as
// reflectanceTristimulus integrates its 1 nm extension.
Eigen::MatrixXd gridWeights(const Observer& observer, const Spectrum& illuminant) {
  std::vector<Eigen::Vector3d> w = reflectanceWeights(observer, illuminant);
  Eigen::MatrixXd grid = Eigen::MatrixXd::Zero(3, kGridWavelengths);
  for (int node = 0; node < kSpectrumSamples; ++node) {
    int k0 = 0, k1 = 0;
    double w1 = 0.0;
    gridShares(node, k0, k1, w1);
    grid.col(k0) += (1.0 - w1) * w[static_cast<std::size_t>(node)];
    grid.col(k1) += w1 * w[static_cast<std::size_t>(node)];
  }
  return grid;
}

Spectrum denseFromGrid(const Eigen::VectorXd& values) {
  Spectrum s;
  for (int node = 0; node < kSpectrumSamples; ++node) {
    int k0 = 0, k1 = 0;
    double w1 = 0.0;
    gridShares(node, k0, k1, w1);
    s[node] = (1.0 - w1) * values[k0] + w1 * values[k1];
  }
  return s;
}

struct Problem {
  Eigen::VectorXd r;        // r at the grid wavelengths
  Eigen::MatrixXd null;     // N: 81 × 78
  Eigen::MatrixXd target;   // W_T N: 3 × 78
  Eigen::Vector3d rTarget;  // r's XYZ under the target illuminant
  Eigen::Vector3d whiteTarget;
  Eigen::Vector3d rLab;
  double best = -1.0;
  Eigen::VectorXd bestZ;

  double deltaE(const Eigen::Vector3d& xyz) const {
    return prism::deltaE(xyzToLab(xyz, whiteTarget), rLab, DeltaEFormula::Ciede2000);
  }
  bool feasible(const Eigen::VectorXd& z) const {
    Eigen::VectorXd x = r + null * z;
    return x.minCoeff() >= -1e-9 && x.maxCoeff() <= 1.0 + 1e-9;
  }
};

double objective(unsigned n, const double* zData, double* gradient, void* data) {
  auto& p = *static_cast<Problem*>(data);
  Eigen::Map<const Eigen::VectorXd> z(zData, n);
  Eigen::Vector3d xyz = p.rTarget + p.target * z;
  double value = p.deltaE(xyz);
  if (gradient) {
    // ∂ΔE/∂XYZ by central differences (3 evaluations pairs; ΔE00 is evaluated in float, so the
    // step is 1e-4 of the white, ~1e-3 relative accuracy), then the chain rule through W_T N.
    Eigen::Vector3d dXyz;
    for (int c = 0; c < 3; ++c) {
      double h = 1e-4 * p.whiteTarget[c];
      Eigen::Vector3d plus = xyz, minus = xyz;
      plus[c] += h;
      minus[c] -= h;
      dXyz[c] = (p.deltaE(plus) - p.deltaE(minus)) / (2.0 * h);
    }
    Eigen::Map<Eigen::VectorXd>(gradient, n) = p.target.transpose() * dXyz;
  }
  if (value > p.best && p.feasible(Eigen::VectorXd(z))) {
    p.best = value;
    p.bestZ = z;
  }
  return value;
}

// c(z) = [r + N z − 1; −(r + N z)] ≤ 0.
void bounds(unsigned m, double* result, unsigned n, const double* zData, double* gradient, void* data) {
  auto& p = *static_cast<Problem*>(data);
  Eigen::Map<const Eigen::VectorXd> z(zData, n);
  Eigen::VectorXd x = p.r + p.null * z;
  const auto k = static_cast<Eigen::Index>(x.size());
  PRISM_CHECK(m == 2u * static_cast<unsigned>(k));
  Eigen::Map<Eigen::VectorXd> c(result, m);
  c.head(k) = x.array() - 1.0;
  c.tail(k) = -x;
  if (gradient) {
    Eigen::Map<Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>> g(gradient, m, n);
    g.topRows(k) = p.null;
    g.bottomRows(k) = -p.null;
  }
}

// Spherical Fibonacci directions (González 2010) for the starts.
Eigen::Vector3d startDirection(int i, int count) {
  double golden = (1.0 + std::sqrt(5.0)) / 2.0;
  double z = 1.0 - (2.0 * i + 1.0) / count, r = std::sqrt(std::max(0.0, 1.0 - z * z));
  double phi = 2.0 * std::numbers::pi * std::fmod(i / golden, 1.0);
  return {r * std::cos(phi), r * std::sin(phi), z};
}

}  // namespace

double reflectanceDeltaE2000(const Spectrum& a, const Spectrum& b, const Spectrum& illuminant, const Observer& observer) {
  Eigen::Vector3d white = whiteTristimulus(observer, illuminant);
  return deltaE(xyzToLab(reflectanceTristimulus(observer, a, illuminant), white),
                xyzToLab(reflectanceTristimulus(observer, b, illuminant), white), DeltaEFormula::Ciede2000);
}

Metamer findMetamer(const Spectrum& reflectance, const Spectrum& matchIlluminant, const Spectrum& targetIlluminant,
                    const Observer& observer) {
  Problem p;
  p.r = sampleOnGrid(reflectance);
  for (int i = 0; i < kGridWavelengths; ++i)
    if (!(p.r[i] >= 0.0 && p.r[i] <= 1.0))
      throw Error(fmt::format("metamer: the reflectance is {} at {} nm, outside [0, 1]", p.r[i], gridWavelengthNm(i)));
  Eigen::MatrixXd match = gridWeights(observer, matchIlluminant);
  if (!match.allFinite() || match.norm() == 0.0) throw Error("metamer: the match illuminant gives no colour");
  // Under one light the "metamer" is the reflectance itself, every ΔE 0: said rather than shown.
  if (std::ranges::equal(matchIlluminant.values(), targetIlluminant.values()))
    throw Error("metamer: the match and target illuminants are the same light; a metamer matches under one and "
                "differs under another");
  Eigen::HouseholderQR<Eigen::MatrixXd> qr(match.transpose());  // 81 × 3
  Eigen::MatrixXd q = qr.householderQ() * Eigen::MatrixXd::Identity(kGridWavelengths, kGridWavelengths);
  p.null = q.rightCols(kGridWavelengths - 3);
  Eigen::MatrixXd targetWeights = gridWeights(observer, targetIlluminant);
  if (!targetWeights.allFinite() || targetWeights.norm() == 0.0) throw Error("metamer: the target illuminant gives no colour");
  p.target = targetWeights * p.null;
  p.rTarget = targetWeights * p.r;
  p.whiteTarget = whiteTristimulus(observer, targetIlluminant);
  p.rLab = xyzToLab(p.rTarget, p.whiteTarget);
  const auto n = static_cast<unsigned>(p.null.cols());
  p.bestZ = Eigen::VectorXd::Zero(n);
  p.best = 0.0;

  const int starts = 12;
  for (int s = 0; s < starts; ++s) {
    // A feasible start: halfway to the bound along the direction that moves the target colour
    // most towards one of 12 directions in XYZ.
    Eigen::VectorXd u = p.target.transpose() * startDirection(s, starts);
    Eigen::VectorXd nu = p.null * u;
    double tMax = std::numeric_limits<double>::infinity();
    for (int k = 0; k < kGridWavelengths; ++k) {
      if (nu[k] > 1e-15) tMax = std::min(tMax, (1.0 - p.r[k]) / nu[k]);
      if (nu[k] < -1e-15) tMax = std::min(tMax, -p.r[k] / nu[k]);
    }
    if (!(tMax > 0.0) || !std::isfinite(tMax)) continue;
    std::vector<double> z(n);
    Eigen::Map<Eigen::VectorXd>(z.data(), n) = 0.5 * tMax * u;
    nlopt::opt opt(nlopt::LD_SLSQP, n);
    opt.set_max_objective(objective, &p);
    opt.add_inequality_mconstraint(bounds, &p, std::vector<double>(2 * kGridWavelengths, 1e-10));
    opt.set_xtol_rel(1e-6);
    opt.set_maxeval(400);
    double value = 0.0;
    try {
      opt.optimize(z, value);
    } catch (const nlopt::roundoff_limited&) {  // the best feasible point seen is kept anyway
    } catch (const std::runtime_error&) {       // SLSQP's "more than iter iterations" and kin
    }
  }
  Metamer result;
  result.gridValues = (p.r + p.null * p.bestZ).cwiseMax(0.0).cwiseMin(1.0);
  // r + b on the 1 nm grid: r itself plus b's piecewise-linear extension, so that a reflectance
  // that is not piecewise linear on the grid keeps its shape between the grid wavelengths.
  Spectrum b = denseFromGrid(result.gridValues - p.r);
  result.reflectance = reflectance + b;
  result.targetDeltaE2000 = reflectanceDeltaE2000(reflectance, result.reflectance, targetIlluminant, observer);
  return result;
}

}  // namespace prism::prt
