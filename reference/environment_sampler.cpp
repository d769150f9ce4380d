#include "reference/environment_sampler.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "core/error.h"
#include "core/parallel_for.h"

namespace prism::reference {
namespace {

constexpr float kTwoPi = 2.0f * std::numbers::pi_v<float>;
constexpr int kCells = EnvironmentSampler::kRows * EnvironmentSampler::kCols;

// The direction at fractions (s, t) ∈ [0, 1]² of cell (row, col).
glm::vec3 cellDirection(int row, int col, float s, float t) {
  const float cosTheta = 1.0f - 2.0f * (static_cast<float>(row) + s) / static_cast<float>(EnvironmentSampler::kRows);
  const float phi = kTwoPi * (static_cast<float>(col) + t) / static_cast<float>(EnvironmentSampler::kCols);
  const float sinTheta = std::sqrt(std::max(0.0f, 1.0f - cosTheta * cosTheta));
  return {sinTheta * std::cos(phi), cosTheta, sinTheta * std::sin(phi)};
}

}  // namespace

EnvironmentSampler::EnvironmentSampler(const TechniqueEnvironment& environment, const Observer& observer,
                                       unsigned threads) {
  // What the observer sees of a direction's light: Σ L(λ)·(x̄ + ȳ + z̄)(λ) every 40 nm over 420–660.
  std::vector<double> lambdaNm, response;
  for (double lambda = 420.0; lambda <= 660.0; lambda += 40.0) {
    lambdaNm.push_back(lambda);
    response.push_back(observer.at(lambda).sum());
  }
  std::vector<double> weight(kCells, 0.0);
  parallelFor(kCells, threads, [&](std::size_t cell) {
    const int row = static_cast<int>(cell) / kCols, col = static_cast<int>(cell) % kCols;
    double sum = 0.0;
    for (const float s : {0.125f, 0.375f, 0.625f, 0.875f})
      for (const float t : {0.125f, 0.375f, 0.625f, 0.875f}) {
        const glm::vec3 towards = cellDirection(row, col, s, t);
        for (std::size_t k = 0; k < lambdaNm.size(); ++k)
          sum += std::max(0.0, environment.radiance(towards, lambdaNm[k])) * response[k];
      }
    weight[cell] = std::isfinite(sum) ? sum : 0.0;
  });
  // Each cell weighed at least as its brightest neighbour: a light that covers part of a cell
  // and none of its points (a sun's edge) is still aimed at, not left to the BRDF's samples alone.
  std::vector<double> dilated(weight);
  for (int row = 0; row < kRows; ++row)
    for (int col = 0; col < kCols; ++col)
      for (int dr = -1; dr <= 1; ++dr)
        for (int dc = -1; dc <= 1; ++dc) {
          const int r = row + dr, c = (col + dc + kCols) % kCols;
          if (r < 0 || r >= kRows) continue;
          double& w = dilated[static_cast<std::size_t>(row * kCols + col)];
          w = std::max(w, 0.25 * weight[static_cast<std::size_t>(r * kCols + c)]);
        }
  weight = std::move(dilated);
  double total = 0.0;
  std::vector<double> cumulative;
  cumulative.reserve(kCells);
  for (double w : weight) cumulative.push_back(total += w);
  if (!(total > 0.0) || !std::isfinite(total)) return;
  mCumulative = std::move(cumulative);
  const double cellSolidAngle = 4.0 * std::numbers::pi / kCells;
  mPdf.resize(kCells);
  for (int cell = 0; cell < kCells; ++cell)
    mPdf[static_cast<std::size_t>(cell)] = static_cast<float>(weight[static_cast<std::size_t>(cell)] / (total * cellSolidAngle));
}

EnvironmentSampler::Direction EnvironmentSampler::sample(double u0, float u1, float u2) const {
  PRISM_CHECK(!empty());
  const double target = u0 * mCumulative.back();
  std::size_t cell = static_cast<std::size_t>(std::upper_bound(mCumulative.begin(), mCumulative.end(), target) -
                                              mCumulative.begin());
  cell = std::min<std::size_t>(cell, kCells - 1);
  while (mPdf[cell] <= 0.0f && cell > 0) --cell;  // u0·total rounded up to the total: the last cell with weight
  const int row = static_cast<int>(cell) / kCols, col = static_cast<int>(cell) % kCols;
  // Uniform in cos θ and azimuth within the cell: uniform in solid angle.
  return {cellDirection(row, col, u1, u2), mPdf[cell]};
}

float EnvironmentSampler::pdf(const glm::vec3& towards) const {
  if (empty()) return 0.0f;
  const int row = std::clamp(static_cast<int>((1.0f - towards.y) * 0.5f * kRows), 0, kRows - 1);
  float phi = std::atan2(towards.z, towards.x);
  if (phi < 0.0f) phi += kTwoPi;
  const int col = std::clamp(static_cast<int>(phi / kTwoPi * kCols), 0, kCols - 1);
  return mPdf[static_cast<std::size_t>(row * kCols + col)];
}

}  // namespace prism::reference
