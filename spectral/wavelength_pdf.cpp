#include "spectral/wavelength_pdf.h"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "core/error.h"

namespace prism {

std::vector<double> WavelengthPdf::binEdges(double minNm, double maxNm) {
  PRISM_CHECK(minNm >= kLambdaMinNm && maxNm <= kLambdaMaxNm && minNm < maxNm);
  std::vector<double> edges;
  for (double e = minNm; e < maxNm; e += 1.0) edges.push_back(e);
  edges.push_back(maxNm);
  return edges;
}

WavelengthPdf::WavelengthPdf(std::vector<double> edgesNm, std::vector<double> weight)
    : mEdgesNm(std::move(edgesNm)), mDensity(std::move(weight)) {
  PRISM_CHECK(mDensity.size() + 1 == mEdgesNm.size());
  mCdf.push_back(0.0);
  for (std::size_t i = 0; i < mDensity.size(); ++i) {
    PRISM_CHECK(mDensity[i] > 0.0);
    mCdf.push_back(mCdf.back() + mDensity[i] * (mEdgesNm[i + 1] - mEdgesNm[i]));
  }
  const double total = mCdf.back();
  for (double& c : mCdf) c /= total;
  for (double& d : mDensity) d /= total;
}

WavelengthPdf WavelengthPdf::observerResponse(const Observer& obs, double minNm, double maxNm) {
  std::vector<double> edges = binEdges(minNm, maxNm);
  std::vector<double> value;
  double mean = 0.0;
  for (std::size_t i = 0; i + 1 < edges.size(); ++i) {
    value.push_back(obs.at(0.5 * (edges[i] + edges[i + 1])).sum());
    mean += value.back();
  }
  mean /= static_cast<double>(value.size());
  if (!(mean > 0.0)) {
    std::ostringstream message;
    message << obs.name << " does not respond within " << minNm << "–" << maxNm
            << " nm: no wavelength there can be importance-sampled";
    throw Error(message.str());
  }
  const double floor = 1e-3 * mean;
  for (double& v : value) v = std::max(v, floor);
  return WavelengthPdf(std::move(edges), std::move(value));
}

WavelengthPdf WavelengthPdf::lightsAndObserver(const Spectrum& emission, const Observer& obs, double minNm,
                                               double maxNm) {
  WavelengthPdf observerPdf = observerResponse(obs, minNm, maxNm);
  const std::vector<double>& edges = observerPdf.mEdgesNm;
  // ∫ E·c̄ over each bin, per curve, by Simpson's rule: exact where the bin lies between two 1 nm
  // nodes, on which E and c̄ are both linear.
  auto product = [&](double lambdaNm) -> Eigen::Vector3d {
    return std::max(emission.at(lambdaNm), 0.0) * obs.at(lambdaNm);
  };
  std::vector<Eigen::Vector3d> curveMass;
  Eigen::Vector3d total = Eigen::Vector3d::Zero();
  for (std::size_t i = 0; i + 1 < edges.size(); ++i) {
    const double a = edges[i], b = edges[i + 1];
    const Eigen::Vector3d atA = product(a), atMid = product(0.5 * (a + b)), atB = product(b);
    Eigen::Vector3d mass = (b - a) / 6.0 * (atA + 4.0 * atMid + atB);
    curveMass.push_back(mass);
    total += mass;
  }
  // Each curve the lights reach gets an equal share: Σ_c E·c̄_c / ∫E·c̄_c.
  std::vector<double> lightMass(curveMass.size(), 0.0);
  int curves = 0;
  for (int c = 0; c < 3; ++c) {
    if (!(total[c] > 0.0) || !std::isfinite(total[c])) continue;
    ++curves;
    for (std::size_t i = 0; i < curveMass.size(); ++i) lightMass[i] += curveMass[i][c] / total[c];
  }
  if (curves == 0) return observerPdf;
  std::vector<double> density;
  for (std::size_t i = 0; i < lightMass.size(); ++i) {
    density.push_back((1.0 - kLightsDefensiveFraction) * lightMass[i] / (curves * (edges[i + 1] - edges[i])) +
                      kLightsDefensiveFraction * observerPdf.mDensity[i]);
  }
  return WavelengthPdf(edges, std::move(density));
}

double WavelengthPdf::density(double lambdaNm) const {
  if (lambdaNm < mEdgesNm.front() || lambdaNm > mEdgesNm.back()) return 0.0;
  auto it = std::upper_bound(mEdgesNm.begin(), mEdgesNm.end(), lambdaNm);
  std::size_t bin = std::min(static_cast<std::size_t>(std::max<std::ptrdiff_t>(it - mEdgesNm.begin() - 1, 0)),
                             mDensity.size() - 1);
  return mDensity[bin];
}

WavelengthPdf::Sample WavelengthPdf::invert(double u) const {
  auto it = std::upper_bound(mCdf.begin(), mCdf.end(), u);
  std::size_t bin = std::min(static_cast<std::size_t>(std::max<std::ptrdiff_t>(it - mCdf.begin() - 1, 0)),
                             mDensity.size() - 1);
  const double width = mEdgesNm[bin + 1] - mEdgesNm[bin];
  const double t = (u - mCdf[bin]) / (mDensity[bin] * width);
  return {mEdgesNm[bin] + std::clamp(t, 0.0, 1.0) * width, mDensity[bin]};
}

}  // namespace prism
