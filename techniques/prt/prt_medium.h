// PRT objects inside a medium (the scene's water) or behind a nebula, on the CPU side: the
// medium's coefficients at each projection's nodes for the forward pass's buffer, and the
// fragment shader's sum over them
// (shaders/shared/prt_medium.glsl says what the sum is and why it is exact for the 5 nm
// reference and reduces to prtXyz for spectral PRT when nothing dims).
#pragma once

#include <vector>

#include <glm/glm.hpp>

#include "spectral/spectrum.h"
#include "techniques/prt/prt_evaluation.h"
#include "techniques/prt/prt_shared.h"

namespace prism::prt {

// A box of homogeneous medium: extinction σt and the diffuse attenuation Kd of light from above
// (1/m), world space.
struct PrtMedium {
  glm::vec3 boxMin{0.0f};
  glm::vec3 boxMax{0.0f};
  Spectrum sigmaT;
  Spectrum kd;
};

// Columns for the SVD basis of a scene inside the medium: each environment spectrum (on the 5 nm
// grid) through e^(−σt·s − Kd·z) for view paths s and depths z on {0, 1, 2, 4, 8, 16, 32} m, the
// pair (0, 0) left out. A textured material's node sum is exact only where T·E lies in the
// basis's span as E does (prt_medium.glsl), so its basis holds the light as the medium leaves it
// too.
std::vector<Eigen::VectorXd> attenuatedSpectra(const std::vector<Eigen::VectorXd>& environment, const PrtMedium& medium);

// The projection's nodes with the medium's σt and Kd at their wavelengths (no medium: zeros; a
// nebula still dims by the nodes' wavelengths).
std::vector<shared::PrtMediumNode> mediumNodes(const PrtProjection& projection, const PrtMedium* medium);

// The fragment shader's tristimulus of one projection at a point seen from `camera`, inside the
// medium (null: none) and behind `nebulaDepthUm` of a nebula: Σ_q T(λ_q)·e_q·ρ_q over the nodes,
// ρ_q from `nodeReflectances` (an untextured material's exact one,
// PrtProjection::nodeReflectances) or, when null, from the projection R̂ (a textured material's).
// Where nothing dims it is prtXyz, as in prt.frag; clamped at 0 either way (prtShownXyz).
glm::vec3 prtXyzThroughMedium(const shared::PrtBasisIrradiance& irradiance, const shared::PrtReflectance& reflectance,
                              int basisCount, const std::vector<shared::PrtMediumNode>& nodes,
                              const std::vector<glm::vec3>* nodeReflectances, const PrtMedium* medium,
                              const glm::vec3& camera, const glm::vec3& point, float nebulaDepthUm = 0.0f);

}  // namespace prism::prt
