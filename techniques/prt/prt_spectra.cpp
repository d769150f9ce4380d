#include "techniques/prt/prt_spectra.h"

#include <algorithm>
#include <cmath>
#include <utility>

#include <fmt/format.h>

#include "core/error.h"
#include "shared_cpp.h"
#include "spectral/thin_svd.h"

namespace prism::prt {

double gridWavelengthNm(int i) { return kGridMinNm + kGridStepNm * i; }

std::vector<double> gridWavelengthsNm() {
  std::vector<double> lambdas;
  for (int i = 0; i < kGridWavelengths; ++i) lambdas.push_back(gridWavelengthNm(i));
  return lambdas;
}

Eigen::VectorXd sampleOnGrid(const Spectrum& spectrum) {
  Eigen::VectorXd v(kGridWavelengths);
  for (int i = 0; i < kGridWavelengths; ++i) v[i] = spectrum.at(gridWavelengthNm(i));
  return v;
}

Eigen::MatrixXd observerOnGrid(const Observer& observer) {
  const double scale = absoluteTristimulusScale(observer) / double(shared::kLumensPerWatt);
  Eigen::MatrixXd cmf(kGridWavelengths, 3);
  for (int i = 0; i < kGridWavelengths; ++i) cmf.row(i) = observer.at(gridWavelengthNm(i)).transpose() * scale;
  return cmf;
}

SpectralBasis::SpectralBasis(const std::vector<Eigen::VectorXd>& spectra,
                             const std::vector<std::vector<Eigen::VectorXd>>& groups) {
  std::size_t total = spectra.size();
  for (const auto& group : groups) total += group.size();
  Eigen::MatrixXd columns(kGridWavelengths, static_cast<Eigen::Index>(total));
  Eigen::Index used = 0;
  auto add = [&](const Eigen::VectorXd& s, double scale) {
    PRISM_CHECK(s.size() == kGridWavelengths);
    const double norm = s.norm();
    if (!(norm > 0.0) || !std::isfinite(norm)) return;  // a black or broken spectrum adds nothing
    columns.col(used++) = s / scale;
  };
  for (const Eigen::VectorXd& s : spectra) add(s, s.norm());
  for (const auto& group : groups) {
    double longest = 0.0;
    for (const Eigen::VectorXd& s : group)
      if (std::isfinite(s.norm())) longest = std::max(longest, s.norm());
    for (const Eigen::VectorXd& s : group) add(s, longest);
  }
  if (used == 0) throw Error("spectral basis: no non-zero spectrum to decompose");
  LeftSingularVectors svd = leftSingularVectors(columns.leftCols(used));
  mVectors = std::move(svd.vectors);
  mSingularValues = std::move(svd.values);
}

Eigen::MatrixXd SpectralBasis::leading(int m) const {
  if (m < 1 || m > available())
    throw Error(fmt::format("spectral basis: size {} out of range 1..{}", m, available()));
  return mVectors.leftCols(m);
}

double SpectralBasis::capturedEnergy(int m) const {
  double total = mSingularValues.squaredNorm();
  return mSingularValues.head(std::min(m, available())).squaredNorm() / total;
}

}  // namespace prism::prt
