// Spherical harmonics on the CPU, around shaders/shared/spherical_harmonics.glsl (whose basis
// functions every routine here evaluates): projection of a directional function by quadrature,
// and rotation of coefficients, so that an environment turns at run time without being projected
// again (Sloan et al. 2002, §6; Green 2003, "Spherical Harmonic Lighting: The Gritty Details", §6).
#pragma once

#include <functional>

#include <Eigen/Core>
#include <glm/glm.hpp>

#include "techniques/prt/prt_shared.h"

namespace prism::prt {

using ShVector = Eigen::Matrix<double, 25, 1>;
using ShRotation = Eigen::Matrix<double, 25, 25>;

ShVector toShVector(const shared::Sh25& s);
shared::Sh25 toSh25(const ShVector& v);
ShVector evaluateSh(const glm::dvec3& dir);  // the shared basis, in double

// ∫ f(ω) Y_k(ω) dω by a product rule: Gauss–Legendre in cos θ on each hemisphere apart (exact
// for functions polynomial in z on each, even with a jump at the horizon) × `phiSteps` equal
// steps in φ (exact for trigonometric polynomials of degree < phiSteps). Polynomials of degree
// < 2·zNodes in (x, y, z) are integrated exactly.
ShVector projectOnSh(const std::function<double(const glm::dvec3& dir)>& f, int zNodes = 48, int phiSteps = 96);

// The matrix D with D·c the coefficients of f(Rᵀω) when c are those of f(ω): f turned by R
// (orthonormal, det +1). Block diagonal, one (2l+1)² block per band, each found exactly from the
// basis at 2(2l+1) fixed directions by least squares (a band is closed under rotation, so the fit
// has no residual beyond rounding).
ShRotation shRotation(const glm::dmat3& rotation);

}  // namespace prism::prt
