#include "techniques/atmosphere/wavelength_optimiser.h"

#include <algorithm>
#include <cmath>

#include <Eigen/Dense>
#include <nlopt.hpp>

#include "spectral/observer.h"

namespace prism::atmosphere {
namespace {

using Matrix34 = Eigen::Matrix<double, 3, 4>;

double lumensPerWatt() { return absoluteTristimulusScale(observer("cie1931")); }  // 683

struct Problem {
  const SkySamples& samples;
  const SpectralSky& reference;
  std::vector<double> exposure;      // per elevation
  std::vector<double> weight;        // per elevation, normalised to sum 1 over samples
  std::vector<Eigen::Vector3d> referenceLab;

  Problem(const SkySamples& s, const SpectralSky& r, double lowSunWeight) : samples(s), reference(r) {
    exposure = exposures(s, r.xyz);
    double total = 0.0;
    for (double e : s.sunElevationsDeg) {
      weight.push_back(e <= 10.0 ? lowSunWeight : 1.0);
      total += weight.back() * double(s.zenith.size());
    }
    for (double& w : weight) w /= total;
    for (std::size_t e = 0; e < s.sunElevationsDeg.size(); ++e) {
      for (std::size_t d = 0; d < s.zenith.size(); ++d) {
        referenceLab.push_back(exposedLab(r.xyz[s.index(e, d)], exposure[e]));
      }
    }
  }

  Eigen::Vector4d radiance(std::size_t i, const std::array<double, 4>& lambda) const {
    return Eigen::Vector4d(reference.at(i, lambda[0]), reference.at(i, lambda[1]),
                           reference.at(i, lambda[2]), reference.at(i, lambda[3]));
  }

  // Weighted mean ΔE*ab² of XYZ = M·L (M absolute, ×683 included).
  double objective(const std::array<double, 4>& lambda, const Matrix34& m) const {
    double sum = 0.0;
    for (std::size_t e = 0; e < samples.sunElevationsDeg.size(); ++e) {
      for (std::size_t d = 0; d < samples.zenith.size(); ++d) {
        std::size_t i = samples.index(e, d);
        Eigen::Vector3d lab = exposedLab(m * radiance(i, lambda), exposure[e]);
        sum += weight[e] * (lab - referenceLab[i]).squaredNorm();
      }
    }
    return sum;
  }

  static Matrix34 matrixOf(const std::array<double, 4>& lambda, const std::array<double, 4>& w) {
    const Observer& cie = observer("cie1931");
    Matrix34 m;
    for (int j = 0; j < 4; ++j) m.col(j) = cie.at(lambda[static_cast<std::size_t>(j)]) * w[static_cast<std::size_t>(j)] * lumensPerWatt();
    return m;
  }

  // The weights that best fit exposed XYZ for these wavelengths (weighted linear least squares).
  std::array<double, 4> leastSquaresWeights(const std::array<double, 4>& lambda) const {
    const Observer& cie = observer("cie1931");
    Eigen::Matrix<double, 3, 4> cmf;
    for (int j = 0; j < 4; ++j) cmf.col(j) = cie.at(lambda[static_cast<std::size_t>(j)]) * lumensPerWatt();
    Eigen::Matrix4d normal = Eigen::Matrix4d::Zero();
    Eigen::Vector4d rhs = Eigen::Vector4d::Zero();
    for (std::size_t e = 0; e < samples.sunElevationsDeg.size(); ++e) {
      for (std::size_t d = 0; d < samples.zenith.size(); ++d) {
        std::size_t i = samples.index(e, d);
        Eigen::Vector4d l = radiance(i, lambda);
        Eigen::Matrix<double, 3, 4> a = cmf * l.asDiagonal() * exposure[e];
        normal += weight[e] * a.transpose() * a;
        rhs += weight[e] * a.transpose() * (reference.xyz[i] * exposure[e]);
      }
    }
    Eigen::Vector4d w = normal.ldlt().solve(rhs);
    return {w[0], w[1], w[2], w[3]};
  }
};

// Runs Nelder–Mead from x (left at the best point found); the best value. A stop on rounding
// keeps the best point so far, which is what NLopt leaves in x.
double minimise(nlopt::opt& opt, std::vector<double>& x, int& evaluations) {
  double value = 0.0;
  try {
    opt.optimize(x, value);
  } catch (const nlopt::roundoff_limited&) {
    value = opt.last_optimum_value();
  }
  evaluations += opt.get_numevals();
  return value;
}

}  // namespace

OptimiserResult optimiseWavelengths(const SkySamples& samples, const SpectralSky& reference,
                                    const OptimiserSettings& settings, const Progress& progress) {
  Problem problem(samples, reference, settings.lowSunWeight);
  OptimiserResult result;

  // Grid search over sorted wavelength quadruples.
  std::vector<double> grid;
  for (double l = 380.0; l <= 740.0 + 1e-9; l += settings.gridStepNm) grid.push_back(l);
  struct Candidate {
    double value;
    std::array<double, 4> lambda, weights;
  };
  std::vector<Candidate> candidates;
  const std::size_t n = grid.size();
  std::size_t combos = n * (n - 1) * (n - 2) * (n - 3) / 24, done = 0;
  const std::size_t total = combos + std::size_t(settings.seeds * settings.maxEvaluations8 + settings.maxEvaluations12);
  for (std::size_t a = 0; a < n; ++a)
    for (std::size_t b = a + 1; b < n; ++b)
      for (std::size_t c = b + 1; c < n; ++c)
        for (std::size_t d = c + 1; d < n; ++d) {
          std::array<double, 4> lambda{grid[a], grid[b], grid[c], grid[d]};
          std::array<double, 4> w = problem.leastSquaresWeights(lambda);
          candidates.push_back({problem.objective(lambda, Problem::matrixOf(lambda, w)), lambda, w});
          if (progress && ++done % 64 == 0) progress(done, total);
        }
  std::sort(candidates.begin(), candidates.end(), [](const Candidate& x, const Candidate& y) { return x.value < y.value; });
  result.gridObjective = candidates.front().value;

  // Nelder–Mead over (λ, w) from the best seeds.
  double best = candidates.front().value;
  std::array<double, 4> bestLambda = candidates.front().lambda, bestWeights = candidates.front().weights;
  for (int s = 0; s < std::min<int>(settings.seeds, int(candidates.size())); ++s) {
    const Candidate& seed = candidates[static_cast<std::size_t>(s)];
    std::vector<double> x(8);
    for (std::size_t j = 0; j < 4; ++j) {
      x[j] = seed.lambda[j];
      x[4 + j] = seed.weights[j];
    }
    nlopt::opt opt(nlopt::LN_NELDERMEAD, 8);
    std::vector<double> lower(8, -1e5), upper(8, 1e5), step(8);
    for (std::size_t j = 0; j < 4; ++j) {
      lower[j] = 360.0;
      upper[j] = 830.0;
      step[j] = 5.0;
      step[4 + j] = std::max(std::abs(seed.weights[j]) * 0.1, 1.0);
    }
    opt.set_lower_bounds(lower);
    opt.set_upper_bounds(upper);
    opt.set_initial_step(step);
    opt.set_maxeval(settings.maxEvaluations8);
    opt.set_xtol_rel(1e-7);
    struct Context {
      Problem* problem;
      std::size_t* done;
      std::size_t total;
      const Progress* progress;
    } context{&problem, &done, total, &progress};
    opt.set_min_objective(
        [](const std::vector<double>& v, std::vector<double>&, void* data) {
          auto* c = static_cast<Context*>(data);
          std::array<double, 4> lambda{v[0], v[1], v[2], v[3]}, w{v[4], v[5], v[6], v[7]};
          if (*c->progress && ++*c->done % 64 == 0) (*c->progress)(*c->done, c->total);
          return c->problem->objective(lambda, Problem::matrixOf(lambda, w));
        },
        &context);
    double value = minimise(opt, x, result.evaluations);
    if (value < best) {
      best = value;
      for (std::size_t j = 0; j < 4; ++j) {
        bestLambda[j] = x[j];
        bestWeights[j] = x[4 + j];
      }
    }
  }
  // Sorted by wavelength (the optimiser may swap them).
  std::array<std::size_t, 4> order{0, 1, 2, 3};
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return bestLambda[a] < bestLambda[b]; });
  for (std::size_t j = 0; j < 4; ++j) {
    result.set.lambdaNm[j] = bestLambda[order[j]];
    result.set.weights[j] = bestWeights[order[j]];
  }
  result.objective8 = best;

  // The full 3×4 matrix for the same wavelengths, from the 8-parameter one.
  Matrix34 m = Problem::matrixOf(result.set.lambdaNm, result.set.weights);
  std::vector<double> x(m.data(), m.data() + 12);
  nlopt::opt opt(nlopt::LN_NELDERMEAD, 12);
  std::vector<double> step(12);
  for (std::size_t j = 0; j < 12; ++j) step[j] = std::max(std::abs(x[j]) * 0.05, 1.0);
  opt.set_initial_step(step);
  opt.set_maxeval(settings.maxEvaluations12);
  opt.set_xtol_rel(1e-8);
  struct Context12 {
    Problem* problem;
    std::array<double, 4> lambda;
    std::size_t* done;
    std::size_t total;
    const Progress* progress;
  } context{&problem, result.set.lambdaNm, &done, total, &progress};
  opt.set_min_objective(
      [](const std::vector<double>& v, std::vector<double>&, void* data) {
        auto* c = static_cast<Context12*>(data);
        Matrix34 mm = Eigen::Map<const Matrix34>(v.data());
        if (*c->progress && ++*c->done % 64 == 0) (*c->progress)(*c->done, c->total);
        return c->problem->objective(c->lambda, mm);
      },
      &context);
  double value = minimise(opt, x, result.evaluations);
  Matrix34 fitted = Eigen::Map<const Matrix34>(x.data());
  result.objective12 = std::min(value, best);
  result.set.matrix = (value < best ? fitted : m) / lumensPerWatt();
  result.set.hasMatrix = true;
  if (progress) progress(total, total);
  return result;
}

}  // namespace prism::atmosphere
