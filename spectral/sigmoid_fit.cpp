#include "spectral/sigmoid_fit.h"

#include <Eigen/LU>
#include <algorithm>
#include <cmath>

#include "shared_cpp.h"
#include "spectral/illuminant.h"

namespace prism::shared {
#include "cielab.glsl"
#include "sigmoid.glsl"
}

namespace prism {
namespace {

constexpr double kSpanNm = kLambdaMaxNm - kLambdaMinNm;

glm::vec3 toVec3(const Eigen::Vector3d& v) {
  return {static_cast<float>(v.x()), static_cast<float>(v.y()), static_cast<float>(v.z())};
}

Eigen::Vector3d lab(const Eigen::Vector3d& xyz, const Eigen::Vector3d& white) {
  glm::vec3 l = shared::xyzToLab(toVec3(xyz), toVec3(white));
  return {l.x, l.y, l.z};
}

// ∂(L*, a*, b*)/∂(X, Y, Z).
Eigen::Matrix3d labJacobian(const Eigen::Vector3d& xyz, const Eigen::Vector3d& white) {
  Eigen::Vector3d d;
  for (int c = 0; c < 3; ++c)
    d[c] = shared::labFDerivative(static_cast<float>(xyz[c] / white[c])) / white[c];
  Eigen::Matrix3d j;
  j << 0.0, 116.0 * d[1], 0.0,
       500.0 * d[0], -500.0 * d[1], 0.0,
       0.0, 200.0 * d[1], -200.0 * d[2];
  return j;
}

}  // namespace

const Spectrum& gamutWhiteIlluminant(const RgbColourSpace& gamut) {
  static const Spectrum d65 = illuminant("D65");
  static const Spectrum d60 = daylight(6000.0);
  return gamut.name == "acescg" || gamut.name == "aces2065-1" ? d60 : d65;
}

SigmoidFitter::SigmoidFitter(const RgbColourSpace& gamut, const Spectrum& illuminant,
                             const Observer& obs)
    : mGamut(gamut) {
  // The reflectance is flat beyond [380, 730] nm, so the 1 nm nodes there share one value each
  // end: one node with their summed weight, a quarter fewer sigmoids per residual.
  const std::vector<Eigen::Vector3d> weights = reflectanceWeights(obs, illuminant);
  for (int i = 0; i < kSpectrumSamples; ++i) {
    double lambdaNm = std::clamp<double>(kLambdaMinNm + i, shared::kReflectanceMinNm,
                                         shared::kReflectanceMaxNm);
    double t = (lambdaNm - kLambdaMinNm) / kSpanNm;
    if (!mT.empty() && mT.back() == t) {
      mWeights.back() += weights[static_cast<std::size_t>(i)];
    } else {
      mT.push_back(t);
      mWeights.push_back(weights[static_cast<std::size_t>(i)]);
    }
  }
  mWhiteXyz = Eigen::Vector3d::Zero();
  for (const Eigen::Vector3d& w : weights) mWhiteXyz += w;
}

SigmoidFit SigmoidFitter::fit(const Eigen::Vector3d& linearRgb, const Eigen::Vector3d& seed) const {
  Eigen::Vector3d rgb = linearRgb.cwiseMax(0.0).cwiseMin(1.0);
  Eigen::Vector3d targetLab = lab(mGamut.rgbToXyz * rgb, mWhiteXyz);

  // Residual r = Lab(a) − target.
  auto residual = [&](const Eigen::Vector3d& a) {
    Eigen::Vector3d xyz = Eigen::Vector3d::Zero();
    for (std::size_t i = 0; i < mT.size(); ++i) {
      double t = mT[i];
      auto x = static_cast<float>((a[0] * t + a[1]) * t + a[2]);
      xyz += mWeights[i] * static_cast<double>(shared::sigmoid(x));
    }
    return std::pair{Eigen::Vector3d(lab(xyz, mWhiteXyz) - targetLab), xyz};
  };
  // Its Jacobian ∂r/∂a, at a point whose XYZ is known: taken only where a step is accepted, so
  // the steps Levenberg–Marquardt rejects (most of them near the gamut's edge) cost half.
  auto jacobian = [&](const Eigen::Vector3d& a, const Eigen::Vector3d& xyz) {
    Eigen::Matrix3d dXyz = Eigen::Matrix3d::Zero();
    for (std::size_t i = 0; i < mT.size(); ++i) {
      double t = mT[i];
      auto x = static_cast<float>((a[0] * t + a[1]) * t + a[2]);
      double ds = shared::sigmoidDerivative(x);
      dXyz.col(0) += mWeights[i] * (ds * t * t);
      dXyz.col(1) += mWeights[i] * (ds * t);
      dXyz.col(2) += mWeights[i] * ds;
    }
    return Eigen::Matrix3d(labJacobian(xyz, mWhiteXyz) * dXyz);
  };

  SigmoidFit result;
  Eigen::Vector3d a = seed;
  auto [r, xyz] = residual(a);
  Eigen::Matrix3d j = jacobian(a, xyz);
  double lambda = 1e-3;
  constexpr int kMaxIterations = 200;
  for (result.iterations = 0; result.iterations < kMaxIterations && r.norm() > 1e-5;
       ++result.iterations) {
    Eigen::Matrix3d jtj = j.transpose() * j;
    Eigen::Vector3d g = j.transpose() * r;
    bool improved = false;
    while (!improved && lambda < 1e12) {
      Eigen::Matrix3d damped = jtj;
      damped.diagonal() += lambda * (jtj.diagonal().array() + 1e-12).matrix();
      Eigen::Vector3d step = damped.partialPivLu().solve(-g);
      Eigen::Vector3d candidate = a + step;
      auto [rc, xyzc] = residual(candidate);
      if (rc.allFinite() && rc.norm() < r.norm()) {
        a = candidate, r = rc, j = jacobian(candidate, xyzc);
        lambda = std::max(lambda / 3.0, 1e-9);
        improved = true;
      } else {
        lambda *= 4.0;
      }
    }
    if (!improved) break;
  }

  // x = a0·t² + a1·t + a2 with t = (λ − 360)/470, expanded in λ.
  double s = 1.0 / kSpanNm, o = kLambdaMinNm;
  result.coeffs = glm::vec3(static_cast<float>(a[0] * s * s),
                            static_cast<float>(a[1] * s - 2.0 * a[0] * o * s * s),
                            static_cast<float>(a[0] * o * o * s * s - a[1] * o * s + a[2]));
  result.normalised = a;
  result.deltaE76 = r.norm();
  return result;
}

double SigmoidFitter::deltaE76(const Eigen::Vector3d& linearRgb, const glm::vec3& coeffs) const {
  Eigen::Vector3d rgb = linearRgb.cwiseMax(0.0).cwiseMin(1.0);
  Eigen::Vector3d xyz = Eigen::Vector3d::Zero();
  for (std::size_t i = 0; i < mT.size(); ++i) {
    auto lambdaNm = static_cast<float>(kLambdaMinNm + mT[i] * kSpanNm);
    xyz += mWeights[i] * static_cast<double>(shared::sigmoid((coeffs[0] * lambdaNm + coeffs[1]) * lambdaNm + coeffs[2]));
  }
  return (lab(xyz, mWhiteXyz) - lab(mGamut.rgbToXyz * rgb, mWhiteXyz)).norm();
}

}  // namespace prism
