// How much of a pixel's star light the projection method carries on its basis outside the family
// it was fitted to. Its basis fits the attenuations e^(−g/λ) for g up to
// RenderSettings::basisMaxDepthUm (2 µm): light that reaches the camera through more dust (a cloud
// lit from behind, thick) projects with an error that grows without bound (at 4 elements a narrow
// filter's integral is 2.4 % off at 5 µm, 70 % at 8), while the stars inside the example nebula stay within
// reach. The renderer cannot tell from its image; this coarse march tells before a render.
#pragma once

#include <string>
#include <string_view>

#include "techniques/nebula/nebula_render.h"

namespace prism::nebula {

struct BasisCoverage {
  double worstShare = 0.0;    // the largest share, over the sampled rays, of a ray's star light beyond the family
  double lightDepthUm = 0.0;  // the optical depth x = g + g_s within which 99 % of a ray's star light arrives, at the deepest ray
};

// Over at most rays × rays of `camera`'s pixels (evenly spread; in the cube's units), marched as settings
// march: each sample's star light weighted by its band integral ∫ e^(−x/λ) dλ, and the share of it
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

}  // namespace prism::nebula
