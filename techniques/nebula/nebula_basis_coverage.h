// How much of a pixel's star light the projection method carries on its basis outside the family
// it was fitted to. Its basis fits the attenuations e^(−g/λ) for g up to
// RenderSettings::basisMaxDepthUm (2 µm): light that reaches the camera through more dust (a cloud
// lit from behind, thick) projects with an error that grows without bound (at 4 elements a narrow
// filter's integral is 2.4 % off at 5 µm, 70 % at 8), while the stars inside the example nebula stay within
// reach. The renderer cannot tell from its image; this coarse march tells before a render. It
// tells, too, for every method, how thick the march's steps are: each step's emission and
// scattered light is taken at its middle, e^(−τ/2)·Δt where a step of optical depth τ holds
// (1 − e^(−τ))/τ·Δt, so a step thicker than τ = 0.5 at 380 nm is more than 1 % too dark there, and
// a dense cloud at a hundred steps goes black (a glowing slab 30 thick a step: 10⁻⁵ of its light).
#pragma once

#include <string>
#include <string_view>

#include "techniques/nebula/nebula_render.h"

namespace prism::nebula {

struct BasisCoverage {
  double worstShare = 0.0;    // the largest share, over the sampled rays, of a ray's star light beyond the family
  double lightDepthUm = 0.0;  // the optical depth x = g + g_s within which 99 % of a ray's star light arrives, at the deepest ray
  // Every method: the largest optical depth of one step at 380 nm, over the steps the camera still
  // sees (less than τ = 5 in front of them).
  double thickestStep = 0.0;
  // Every method: the rays sampled, and how many of them meet the cube.
  int rays = 0;
  int raysMeetingCube = 0;
};

// Over at most rays × rays of `camera`'s pixels (evenly spread; in the cube's units), marched as settings
// march: each step's optical depth, and (projection) each sample's star light weighted by its band integral ∫ e^(−x/λ) dλ, and the share of it
// at x beyond the family. Rays with less than 1 % of the brightest ray's star light are left out,
// as maxRelativeError leaves out such pixels. Other methods: nothing beyond. (Light–density's 2D
// basis is fitted over the same depths, but widening them does not lower its error behind thick
// dust — README, "Spectral nebulae" — so this does not speak for it.)
BasisCoverage basisCoverage(const NebulaRenderer& renderer, const RenderSettings& settings, const NebulaCamera& camera,
                            int rays = 32);

// One line for stderr when some ray gathers more than 1 % of its star light beyond the basis
// ("" otherwise): how much, how deep, and what fits it (a deeper basis, or the analytic method).
// `deeperBasis` names the way to ask for one where the user is ("--basis-depth 12 --basis 6", or
// the scene's keys).
std::string basisCoverageWarning(const BasisCoverage& coverage, const RenderSettings& settings,
                                 std::string_view deeperBasisFormat);

// One line for stderr when a step the camera sees is thicker than τ = 0.5 at 380 nm ("" otherwise):
// how thick, how much darker such a step comes out, and the step count that keeps every step
// within 0.5. `moreStepsFormat` names the way to ask for it ("--steps {}", or the scene's key).
std::string stepThicknessWarning(const BasisCoverage& coverage, const RenderSettings& settings,
                                 std::string_view moreStepsFormat);

// One line for stderr when none of the sampled rays meets the nebula's cube ("" otherwise): the
// camera looks away from it (a new-user review's image came out black with no word).
std::string outOfViewWarning(const BasisCoverage& coverage);

}  // namespace prism::nebula
