// The SH basis, its projection and rotation, and the run-time PRT sums (shaders/shared/), closed
// form where possible.
#include <cmath>
#include <numbers>
#include <random>

#include <gtest/gtest.h>
#include <glm/gtc/matrix_transform.hpp>

#include "techniques/prt/sh_tools.h"

namespace prism::prt {
namespace {

glm::dmat3 someRotation(double angle, glm::dvec3 axis) {
  return glm::dmat3(glm::rotate(glm::dmat4(1.0), angle, glm::normalize(axis)));
}

TEST(ShBasis, IsOrthonormalByQuadrature) {
  // Each basis function projected on the basis is a unit vector: Gauss–Legendre × equal φ steps
  // integrate the degree-8 products exactly; what is left is the basis's float rounding (1e-6).
  for (int k = 0; k < 25; ++k) {
    ShVector p = projectOnSh([k](const glm::dvec3& d) { return evaluateSh(d)[k]; }, 12, 24);
    for (int j = 0; j < 25; ++j) EXPECT_NEAR(p[j], j == k ? 1.0 : 0.0, 1e-6) << "k=" << k << " j=" << j;
  }
}

TEST(ShBasis, MatchesClosedFormsAtKnownDirections) {
  // Y_00 = 1/(2√π); Y_20(+z) = √(5/π)/2; Y_40(+z) = 3/(2√π) (P_l(1) = 1, N_l0 = √((2l+1)/4π)).
  shared::Sh25 z = shared::shEvaluate(glm::vec3(0.0f, 0.0f, 1.0f));
  EXPECT_NEAR(z.c[0], 0.5 / std::sqrt(std::numbers::pi), 1e-7);
  EXPECT_NEAR(z.c[6], 0.5 * std::sqrt(5.0 / std::numbers::pi), 1e-6);
  EXPECT_NEAR(z.c[20], 1.5 / std::sqrt(std::numbers::pi), 1e-6);
  for (int k : {1, 3, 4, 5, 7, 8, 16, 24}) EXPECT_EQ(z.c[k], 0.0f) << k;
}

TEST(ShBasis, ClampedCosineIsTheProjectionOfMaxCos) {
  // About +z the kink of max(cos θ, 0) sits on the rule's hemisphere split: exact to rounding.
  ShVector p = projectOnSh([](const glm::dvec3& d) { return std::max(d.z, 0.0); });
  ShVector a = toShVector(shared::shClampedCosine(glm::vec3(0.0f, 0.0f, 1.0f)));
  for (int k = 0; k < 25; ++k) EXPECT_NEAR(p[k], a[k], 2e-6) << k;
  // About another axis the kink crosses the cells: the rule is first order there (48 × 96 cells
  // give ~1e-3 absolute).
  glm::dvec3 n = glm::normalize(glm::dvec3(0.3, -0.5, 0.8));
  ShVector q = projectOnSh([n](const glm::dvec3& d) { return std::max(glm::dot(n, d), 0.0); });
  ShVector b = toShVector(shared::shClampedCosine(glm::vec3(n)));
  for (int k = 0; k < 25; ++k) EXPECT_NEAR(q[k], b[k], 2e-3) << k;
}

TEST(ShRotation, TurnsAFunctionAsProjectingItTurnedWould) {
  // f(ω) = a polynomial of degree 4 (band-limited), turned by R: D c must equal the projection of
  // f(Rᵀω); both are exact to float rounding of the basis (1e-5 on coefficients of size ~1).
  auto f = [](const glm::dvec3& d) { return 1.0 + 0.7 * d.x - 0.4 * d.y * d.z + 0.9 * d.z * d.z * d.x * d.y + 0.3 * d.x * d.x * d.x; };
  glm::dmat3 r = someRotation(1.1, {0.2, 0.9, -0.4});
  ShVector turned = shRotation(r) * projectOnSh(f, 12, 24);
  ShVector direct = projectOnSh([&](const glm::dvec3& d) { return f(glm::transpose(r) * d); }, 12, 24);
  for (int k = 0; k < 25; ++k) EXPECT_NEAR(turned[k], direct[k], 1e-5) << k;
  // A rotation's matrix is orthogonal, and composes.
  ShRotation d = shRotation(r);
  EXPECT_LT((d.transpose() * d - ShRotation::Identity()).cwiseAbs().maxCoeff(), 1e-5);
  glm::dmat3 s = someRotation(-0.6, {1.0, 0.1, 0.3});
  EXPECT_LT((shRotation(s * r) - shRotation(s) * d).cwiseAbs().maxCoeff(), 1e-5);
}

TEST(PrtSums, AreTheTwoDotProducts) {
  // Ê_j = Σ_k L̃_jk T̃_k, XYZ = Σ_j Ê_j R̂_j, against Eigen in double on random inputs; float
  // sums of 25 and 16 terms of size ~1: 1e-5 relative.
  std::mt19937 rng(7);
  std::uniform_real_distribution<float> u(-1.0f, 1.0f);
  for (int trial = 0; trial < 20; ++trial) {
    int m = 1 + trial % 16;
    shared::PrtEnvironment env;
    shared::PrtReflectance refl;
    shared::Sh25 t;
    Eigen::MatrixXd l(16, 25), r(3, 16);
    Eigen::VectorXd tv(25);
    for (int k = 0; k < 25; ++k) tv[k] = t.c[k] = u(rng);
    for (int j = 0; j < 16; ++j) {
      for (int k = 0; k < 25; ++k) l(j, k) = env.basis[j].c[k] = u(rng);
      refl.r[j] = glm::vec3(u(rng), u(rng), u(rng));
      for (int c = 0; c < 3; ++c) r(c, j) = refl.r[j][c];
    }
    shared::PrtBasisIrradiance e = shared::prtVertexIrradiance(env, t, m);
    Eigen::VectorXd expectE = l.topRows(m) * tv;
    for (int j = 0; j < 16; ++j) EXPECT_NEAR(e.e[j], j < m ? expectE[j] : 0.0, 1e-5);
    glm::vec3 xyz = shared::prtXyz(e, refl, m);
    Eigen::Vector3d expect = r.leftCols(m) * expectE;
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(xyz[c], expect[c], 1e-4 * (1.0 + std::abs(expect[c])));
  }
}

}  // namespace
}  // namespace prism::prt
