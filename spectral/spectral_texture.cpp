#include "spectral/spectral_texture.h"

#include <algorithm>
#include <cmath>

#include "core/error.h"

namespace prism {
namespace {

int wrapped(int i, int size) { return ((i % size) + size) % size; }

}  // namespace

Eigen::Map<const Eigen::VectorXf> SpectralTexture::texel(int x, int y) const {
  const std::size_t k = static_cast<std::size_t>(channels());
  const std::size_t index = (static_cast<std::size_t>(y) * static_cast<std::size_t>(width) + static_cast<std::size_t>(x)) * k;
  return Eigen::Map<const Eigen::VectorXf>(coefficients.data() + index, channels());
}

Eigen::MatrixXd basisAt(const SpectralTexture& texture, const std::vector<double>& lambdasNm) {
  const std::vector<double>& w = texture.wavelengthsNm;
  Eigen::MatrixXd out(static_cast<Eigen::Index>(lambdasNm.size()), texture.basis.cols());
  for (std::size_t i = 0; i < lambdasNm.size(); ++i) {
    const Eigen::Index row = static_cast<Eigen::Index>(i);
    const double lambda = lambdasNm[i];
    if (lambda <= w.front()) {
      out.row(row) = texture.basis.row(0);
    } else if (lambda >= w.back()) {
      out.row(row) = texture.basis.row(texture.basis.rows() - 1);
    } else {
      const auto upper = std::upper_bound(w.begin(), w.end(), lambda);
      const Eigen::Index b = upper - w.begin(), a = b - 1;
      const double t = (lambda - w[static_cast<std::size_t>(a)]) / (w[static_cast<std::size_t>(b)] - w[static_cast<std::size_t>(a)]);
      out.row(row) = (1.0 - t) * texture.basis.row(a) + t * texture.basis.row(b);
    }
  }
  return out;
}

Eigen::VectorXd sampleTexels(const SpectralTexture& texture, const glm::vec2& uv) {
  // Wrapped to [0, 1) first (repeat), so that no coordinate is too large for an int.
  auto wrap = [](float t) { return std::isfinite(t) ? t - std::floor(t) : 0.0f; };
  const float x = wrap(uv.x) * static_cast<float>(texture.width) - 0.5f;
  const float y = wrap(uv.y) * static_cast<float>(texture.height) - 0.5f;
  const float x0 = std::floor(x), y0 = std::floor(y);
  const double fx = x - x0, fy = y - y0;
  const int ix = static_cast<int>(x0), iy = static_cast<int>(y0);
  auto at = [&](int dx, int dy) -> Eigen::VectorXd {
    return texture.texel(wrapped(ix + dx, texture.width), wrapped(iy + dy, texture.height)).cast<double>();
  };
  return (1.0 - fy) * ((1.0 - fx) * at(0, 0) + fx * at(1, 0)) + fy * ((1.0 - fx) * at(0, 1) + fx * at(1, 1));
}

double reflectanceAt(const SpectralTexture& texture, const Eigen::VectorXd& c, double lambdaNm) {
  return basisAt(texture, {lambdaNm}).row(0).dot(c);
}

void checkSpectralTexture(const SpectralTexture& t) {
  PRISM_CHECK(t.width >= 1 && t.height >= 1);
  PRISM_CHECK(!t.wavelengthsNm.empty() && t.basis.rows() == static_cast<Eigen::Index>(t.wavelengthsNm.size()));
  PRISM_CHECK(t.basis.cols() >= 1);
  for (std::size_t i = 0; i < t.wavelengthsNm.size(); ++i) {
    PRISM_CHECK(std::isfinite(t.wavelengthsNm[i]));
    PRISM_CHECK(i == 0 || t.wavelengthsNm[i] > t.wavelengthsNm[i - 1]);
  }
  PRISM_CHECK(!t.sampled || t.basis.isIdentity(0.0));
  PRISM_CHECK(t.coefficients.size() == static_cast<std::size_t>(t.width) * static_cast<std::size_t>(t.height) *
                                           static_cast<std::size_t>(t.channels()));
}

}  // namespace prism
