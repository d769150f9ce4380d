// The projection basis's reach (nebula_basis_coverage.h): a cloud whose stars sit inside it stays
// within the family the basis was fitted for; the same cloud, thick and lit from behind, sends its
// light through more dust than that, where projection misses the reference by far more than 2 % —
// and a basis fitted as deep as the coverage says brings it back within 2 %.
#include "techniques/nebula/nebula_basis_coverage.h"

#include <cmath>
#include <cstdio>

#include <gtest/gtest.h>

#include "techniques/nebula/nebula_test_cloud.h"

namespace prism::nebula {
namespace {

RenderSettings projection(int basisSize, double basisDepthUm) {
  RenderSettings s;
  s.method = Method::Projection;
  s.basisSize = basisSize;
  s.basisMaxDepthUm = basisDepthUm;
  s.emissionLines = false;
  return s;
}

double errorAgainstTheReference(const NebulaRenderer& renderer, const RenderSettings& s) {
  RenderSettings r = s;
  r.method = Method::Reference;
  return maxRelativeError(renderer.render(s), renderer.render(r));
}

TEST(NebulaBasisCoverage, AStarInsideTheCloudStaysWithinTheBasis) {
  NebulaModel m = smallCloud("cie1931", 1);
  const RenderSettings s = projection(4, 2.0);
  NebulaRenderer renderer(std::move(m), s);
  const BasisCoverage coverage = basisCoverage(renderer, s, renderer.model().camera);
  std::printf("star inside: share beyond %.4f, 99 %% of the light within %.2f µm\n", coverage.worstShare, coverage.lightDepthUm);
  EXPECT_LE(coverage.worstShare, 0.01);
}

TEST(NebulaBasisCoverage, AThickCloudLitFromBehindNeedsADeeperBasis) {
  NebulaModel m = smallCloud("cie1931", 1);
  m.extinction = 25.0;
  m.stars[0].position = glm::dvec3(0.5, 0.5, 1.4);  // behind the cube, the camera before it
  const RenderSettings shallow = projection(4, 2.0);
  const NebulaRenderer renderer(NebulaModel(m), shallow);
  const BasisCoverage coverage = basisCoverage(renderer, shallow, renderer.model().camera);
  const double shallowError = errorAgainstTheReference(renderer, shallow);
  const RenderSettings deep = projection(6, std::ceil(coverage.lightDepthUm));
  const NebulaRenderer deeper(std::move(m), deep);
  const BasisCoverage deepCoverage = basisCoverage(deeper, deep, deeper.model().camera);
  const double deepError = errorAgainstTheReference(deeper, deep);
  std::printf("lit from behind: share beyond %.3f, 99 %% of the light within %.2f µm, error %.4f; basis 6 to %.0f µm: share %.3f, error %.4f\n",
              coverage.worstShare, coverage.lightDepthUm, shallowError, deep.basisMaxDepthUm, deepCoverage.worstShare, deepError);
  EXPECT_GE(coverage.worstShare, 0.5);
  EXPECT_GT(shallowError, 0.02);  // what the coverage warns of
  EXPECT_LE(deepCoverage.worstShare, 0.01);  // fitted to where 99 % of each ray's light arrives: no warning
  EXPECT_LE(deepError, 0.02);
}

}  // namespace
}  // namespace prism::nebula
