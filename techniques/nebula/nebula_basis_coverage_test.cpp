// The projection basis's reach (nebula_basis_coverage.h): a cloud whose stars sit inside it stays
// within the family the basis was fitted for; the same cloud, thick and lit from behind, sends its
// light through more dust than that, where projection misses the reference by far more than 2 % —
// and a basis fitted as deep as the coverage says brings it back within 2 %. And the march's steps:
// a cloud too dense for them is said, with the step count that fits it.
#include "techniques/nebula/nebula_basis_coverage.h"

#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include <fmt/format.h>
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

// Just past the basis's depth, the warning's figures do not contradict it: it read "up to 1 % …
// (99 % of it within an optical depth of 2.0 µm, the basis 2 µm)".
TEST(NebulaBasisCoverage, TheWarningsFiguresSayTheLightLiesBeyondTheBasis) {
  const RenderSettings s = projection(4, 2.0);
  const std::string warning = basisCoverageWarning({.worstShare = 0.012, .lightDepthUm = 2.001}, s, "--basis-depth {:.0f}");
  EXPECT_NE(warning.find("up to 1.2 % of a pixel's star light"), std::string::npos) << warning;
  EXPECT_NE(warning.find("within an optical depth of 2.01 µm, the basis 2 µm"), std::string::npos) << warning;
  EXPECT_NE(warning.find("--basis-depth 3 fits deeper"), std::string::npos) << warning;
  EXPECT_NE(basisCoverageWarning({.worstShare = 0.5, .lightDepthUm = 2.04}, s, "").find("within an optical depth of 2.04 µm"),
            std::string::npos);
  EXPECT_EQ(basisCoverageWarning({.worstShare = 0.01, .lightDepthUm = 2.5}, s, ""), "");  // 1 % beyond: nothing said
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

// A glowing cloud so dense that a hundred steps are each about 5 optical depths thick at 380 nm:
// every method takes a step's light at its middle, so the image comes out far too dark, and the
// coverage says so; at the step count the warning names (each step within τ = 0.5) the image is
// within 1 % of a march four times finer.
TEST(NebulaBasisCoverage, StepsTooThickForTheCloudAreSaid) {
  NebulaModel m = smallCloud("cie1931", 0);
  m.density = {24, 24, 24, std::vector<float>(24 * 24 * 24, 1.0f)};
  m.extinction = 340.0;
  m.lineGroups = {{"H I Balmer (case B)", 1.0}};
  m.emission = 0.01;
  RenderSettings s;
  s.method = Method::Reference;
  const NebulaRenderer renderer(std::move(m), s);
  auto total = [&](int steps) {
    RenderSettings r = s;
    r.steps = steps;
    double y = 0.0;
    for (const glm::vec3& p : renderer.render(r).pixels) y += p.y;
    return y;
  };
  const BasisCoverage coverage = basisCoverage(renderer, s, renderer.model().camera);
  const std::string warning = stepThicknessWarning(coverage, s, "--steps {:.0f}");
  ASSERT_GT(coverage.thickestStep, 0.5) << "no warning";
  const int advised = static_cast<int>(std::ceil(s.steps * coverage.thickestStep / 0.5));
  EXPECT_NE(warning.find(fmt::format("--steps {} keeps every step within 0.5", advised)), std::string::npos) << warning;
  const double coarse = total(s.steps), enough = total(advised), finer = total(4 * advised);
  std::printf("%s\nY over the image: %d steps %.4g, %d steps %.4g, %d steps %.4g\n", warning.c_str(), s.steps, coarse,
              advised, enough, 4 * advised, finer);
  EXPECT_LT(coarse, 0.8 * finer);
  EXPECT_NEAR(enough, finer, 0.01 * finer);
  RenderSettings thin = s;
  thin.steps = advised;
  EXPECT_EQ(stepThicknessWarning(basisCoverage(renderer, thin, renderer.model().camera), thin, "--steps {:.0f}"), "");
}

// A camera that looks away from the cube: every ray misses it, said (the image came out black
// with no word); looking at it, nothing is said.
TEST(NebulaBasisCoverage, ACameraLookingAwayFromTheCubeIsSaid) {
  NebulaModel m = smallCloud("cie1931", 1);
  m.camera.position = {0.5, 0.5, -1.0};
  m.camera.target = {0.5, 0.5, 0.5};
  const RenderSettings s = projection(4, 2.0);
  const NebulaRenderer renderer(NebulaModel(m), s);
  const BasisCoverage towards = basisCoverage(renderer, s, m.camera);
  EXPECT_EQ(towards.rays, 32 * 32);
  EXPECT_GT(towards.raysMeetingCube, 0);
  EXPECT_EQ(outOfViewWarning(towards), "");
  m.camera.target = {0.5, 0.5, -2.0};
  const BasisCoverage away = basisCoverage(renderer, s, m.camera);
  EXPECT_EQ(away.raysMeetingCube, 0);
  EXPECT_EQ(outOfViewWarning(away), "the camera looks away from the nebula, so its image is black: none of 1024 rays "
                                    "spread over the image meets the nebula's cube (see the camera's position and target)");
  double y = 0.0;
  NebulaModel awayModel = m;
  for (const glm::vec3& p : NebulaRenderer(std::move(awayModel), s).render(s).pixels) y += p.y;
  EXPECT_EQ(y, 0.0) << "what the warning says";
}

}  // namespace
}  // namespace prism::nebula
