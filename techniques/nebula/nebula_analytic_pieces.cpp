#include "techniques/nebula/nebula_analytic_pieces.h"

#include <algorithm>
#include <cmath>

#include "core/gauss_legendre.h"

namespace prism::nebula {

shared::f64::NebulaAnalyticPiece analyticPiece(const PolynomialPiece& filter, const PolynomialPiece& factor,
                                               double lambda0Um, double lambda1Um, bool inversePower5) {
  shared::f64::NebulaAnalyticPiece piece{};
  const PolynomialPiece product = multiply(filter, factor);
  for (int n = 0; n < 4; ++n) {
    piece.cLo[n] = product.coeffs[static_cast<std::size_t>(n)];
    piece.cHi[n] = product.coeffs[static_cast<std::size_t>(n + 4)];
  }
  const double c = 0.5 * (lambda0Um + lambda1Um), h = 0.5 * (lambda1Um - lambda0Um);
  const double epsilon = h / c, g = 1.0 / (1.0 - epsilon);
  piece.bounds = glm::dvec4(lambda0Um, lambda1Um, 1.0 / c, h * g / (c * c));
  std::vector<double> nodes, weights;
  gaussLegendre(24, -1.0, 1.0, nodes, weights);
  std::array<double, 12> v{};
  for (std::size_t i = 0; i < nodes.size(); ++i) {
    const double s = nodes[i], lambda = c + h * s;
    double p = filter.at(lambda) * factor.at(lambda);
    if (inversePower5) p *= std::pow(lambda, -5.0);
    const double gamma = s / ((1.0 + epsilon * s) * g);
    double term = weights[i] * h * p;  // h·w·P·γ^d/d!
    for (std::size_t d = 0; d < v.size(); ++d) {
      v[d] += term;
      term *= gamma / static_cast<double>(d + 1);
    }
  }
  for (int d = 0; d < 4; ++d) {
    piece.series0[d] = v[static_cast<std::size_t>(d)];
    piece.series1[d] = v[static_cast<std::size_t>(d + 4)];
    piece.series2[d] = v[static_cast<std::size_t>(d + 8)];
  }
  return piece;
}

shared::NebulaAnalyticPiece toFloat(const shared::f64::NebulaAnalyticPiece& piece) {
  return {glm::vec4(piece.series0), glm::vec4(piece.series1), glm::vec4(piece.series2),
          glm::vec4(piece.bounds),  glm::vec4(piece.cLo),     glm::vec4(piece.cHi)};
}

AnalyticPieces makeAnalyticPieces(const FilterSet& filters, const std::vector<StarSpectrum>& spectra) {
  AnalyticPieces result;
  for (const auto& spectrum : spectra) {
    bool wien = spectrum.model == StarModel::Wien;
    for (const auto& channel : filters.channels)
      for (const auto& piece : channel.response.pieces) wien = wien && degree(piece) + degree(spectrum.scattering) <= 3;
    result.wienExponentUm.push_back(wien ? wienExponentUm(spectrum.temperatureK) : 0.0);
    PolynomialPiece wienFactor = spectrum.scattering;  // N·P_σ
    for (double& c : wienFactor.coeffs) c *= spectrum.normalisation;
    const PiecewisePolynomial factors = wien ? PiecewisePolynomial{{wienFactor}} : spectrum.fit;
    std::array<std::vector<shared::NebulaAnalyticPiece>, 3> perChannel;
    std::array<std::vector<shared::f64::NebulaAnalyticPiece>, 3> perChannelF64;
    for (std::size_t c = 0; c < 3; ++c)
      for (const auto& filter : filters.channels[c].response.pieces)
        for (const auto& factor : factors.pieces) {
          const double lo = std::max(filter.lambda0Um, factor.lambda0Um), hi = std::min(filter.lambda1Um, factor.lambda1Um);
          if (hi <= lo) continue;
          const shared::f64::NebulaAnalyticPiece d = analyticPiece(filter, factor, lo, hi, wien);
          perChannelF64[c].push_back(d);
          perChannel[c].push_back(toFloat(d));
        }
    result.f32.push_back(std::move(perChannel));
    result.f64.push_back(std::move(perChannelF64));
  }
  return result;
}

}  // namespace prism::nebula
