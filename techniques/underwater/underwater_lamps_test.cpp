// shared/underwater_lamps.glsl compiled as C++: a lamp's single scattering along a view ray under
// water, against the same integral summed by Simpson's rule in double precision, and against the
// closed form of clear water.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>

#include <glm/glm.hpp>

#include "techniques/underwater/underwater_layout.h"

namespace prism::shared {
#include "lights.glsl"
#include "underwater_lamps.glsl"
}  // namespace prism::shared

namespace prism::shared {
namespace {

struct Lamp {
  int type = kLightPoint;
  glm::dvec3 position{0.0};
  glm::dvec3 axis{0.0, -1.0, 0.0};  // where a spot points
  double cosInner = 1.0, cosOuter = 1.0;
};

// σs/(4π) ∫₀^length I(p)/|L − p|² e^(−σt·(s + r_w)) ds at one wavelength (I = 1), by Simpson's rule
// over 400 000 steps of the ray (its first 60/σt metres when it is longer: e^(−60) is nothing).
double simpson(double sigmaS, double sigmaT, glm::dvec3 origin, glm::dvec3 dir, double length, const Lamp& lamp,
               double surfaceY) {
  length = std::min(length, 60.0 / sigmaT);
  auto f = [&](double s) {
    const glm::dvec3 p = origin + dir * s;
    const glm::dvec3 toLamp = lamp.position - p;
    const double d = glm::length(toLamp);
    double profile = 1.0;
    if (lamp.type == kLightSpot) {
      const double t = std::clamp((glm::dot(-toLamp / d, lamp.axis) - lamp.cosOuter) / (lamp.cosInner - lamp.cosOuter),
                                  0.0, 1.0);
      profile = t * t * (3.0 - 2.0 * t);
    }
    const double low = std::min(p.y, lamp.position.y), high = std::max(p.y, lamp.position.y);
    const double share = high <= surfaceY ? 1.0 : low >= surfaceY ? 0.0 : (surfaceY - low) / (high - low);
    return profile / (d * d) * std::exp(-sigmaT * (s + d * share));
  };
  const int n = 400000;
  const double step = length / n;
  double sum = f(0.0) + f(length);
  for (int i = 1; i < n; ++i) sum += (i % 2 == 1 ? 4.0 : 2.0) * f(i * step);
  return sigmaS / (4.0 * std::numbers::pi) * sum * step / 3.0;
}

vec4 gpuSide(const vec4& sigmaS, const vec4& sigmaT, glm::dvec3 origin, glm::dvec3 dir, double length, const Lamp& lamp,
             double surfaceY) {
  const vec3 o(origin), d(glm::normalize(dir)), position(lamp.position), axis(lamp.axis);
  const float cosInner = static_cast<float>(lamp.cosInner), cosOuter = static_cast<float>(lamp.cosOuter);
  const LampRay r = lampRay(o, d, static_cast<float>(length), lamp.type, position, axis, 1.0f, cosOuter);
  vec4 sum(0.0f);
  if (r.scale == 0.0f) return sum;
  for (int n = 0; n < kLampNodeCount; ++n) {
    const LampNode node = lampNode(r, n, o, d, lamp.type, position, axis, cosInner, cosOuter, static_cast<float>(surfaceY));
    sum += node.weight * glm::exp(-sigmaT * node.pathM);
  }
  return sigmaS * r.scale * sum;
}

// Jerlov I to 9C at 440–680 nm span σt of 0.02–2 m⁻¹: four of them in one batch.
const vec4 kSigmaS(0.003f, 0.02f, 0.2f, 1.0f);
const vec4 kSigmaT(0.02f, 0.1f, 0.5f, 2.0f);

// 16 Gauss–Legendre nodes against 400 000 Simpson steps: within 1.3e-3 relative over these rays
// (the worst, endless rays along a spot's side, lit by its soft edge; then a narrow beam crossed,
// and an endless ray in the clearest water 1.4 m from a lamp, whose far tail the equiangular nodes
// sample sparsely, 9.6e-4), below a display's 8-bit step (0.4 %).
constexpr double kTolerance = 2e-3;

void expectMatches(glm::dvec3 origin, glm::dvec3 dir, double length, const Lamp& lamp, double surfaceY,
                   double tolerance) {
  dir = glm::normalize(dir);
  const vec4 got = gpuSide(kSigmaS, kSigmaT, origin, dir, length, lamp, surfaceY);
  double worst = 0.0;
  for (int j = 0; j < 4; ++j) {
    const double want = simpson(kSigmaS[j], kSigmaT[j], origin, dir, length, lamp, surfaceY);
    EXPECT_NEAR(got[j], want, tolerance * want + 1e-12) << "wavelength " << j << ", ray length " << length;
    if (want > 1e-12) worst = std::max(worst, std::abs(got[j] - want) / want);
  }
  std::printf("a ray of %g m: relative error at most %.2g\n", length, worst);
}

TEST(UnderwaterLamps, APointLampsGlowMatchesTheIntegral) {
  Lamp lamp;
  lamp.position = {1.0, -3.0, -4.0};
  const glm::dvec3 camera(0.0, -2.0, 0.0);
  for (double length : {0.5, 3.0, 10.0, 1e30}) {          // before, across and past the lamp; the open water
    expectMatches(camera, {0.0, 0.0, -1.0}, length, lamp, 0.0, kTolerance);   // passing 1.4 m from it
    expectMatches(camera, {0.2, -0.1, -1.0}, length, lamp, 0.0, kTolerance);  // 0.6 m
  }
  lamp.position = {0.02, -2.0, -4.0};  // 2 cm from the ray: the peak the substitution flattens
  expectMatches(camera, {0.0, 0.0, -1.0}, 10.0, lamp, 0.0, kTolerance);
  lamp.position = {0.05, -2.0, 3.0};  // 3 m behind the camera, 5 cm off the ray
  expectMatches(camera, {0.0, 0.0, -1.0}, 1e30, lamp, 0.0, kTolerance);
}

TEST(UnderwaterLamps, ASpotsBeamIsFoundWhereItCrossesTheRay) {
  Lamp spot;
  spot.type = kLightSpot;
  spot.position = {-3.0, -2.0, -6.0};
  spot.axis = glm::normalize(glm::dvec3(1.0, 0.0, 0.1));  // across the view, a 12° beam
  spot.cosInner = std::cos(glm::radians(8.0));
  spot.cosOuter = std::cos(glm::radians(12.0));
  const glm::dvec3 camera(0.0, -2.0, 0.0);
  for (double length : {4.0, 8.0, 1e30}) expectMatches(camera, {0.0, 0.0, -1.0}, length, spot, 0.0, kTolerance);
  // Looking along the beam from beside the lamp, and into it from in front, up to 0.5 m before it.
  expectMatches({-3.0, -1.5, -6.0}, spot.axis, 1e30, spot, 0.0, kTolerance);
  expectMatches({3.0, -1.9, -5.4}, -spot.axis, 5.5, spot, 0.0, kTolerance);
  // A torch seen head on, along its axis: the ray meets the cone's surface only at the apex (the
  // span was lost with the double root, and the torch gave nothing). Inside its inner cone up to
  // the apex, it gives about what a point lamp gives over that part of the ray: through a lamp the
  // integral is infinite, both take the lamp 1 mm from the ray, and the span's end, a double root
  // found to about √ε of the ray's length (mm), moves the last millimetre's share (8 % here).
  const glm::dvec3 front(3.0, -2.0, -5.4);
  const vec4 headOn = gpuSide(kSigmaS, kSigmaT, front, -spot.axis, 20.0, spot, 0.0);
  const vec4 point = gpuSide(kSigmaS, kSigmaT, front, -spot.axis, glm::dot(spot.position - front, -spot.axis),
                             Lamp{.position = spot.position}, 0.0);
  for (int j = 0; j < 4; ++j) EXPECT_NEAR(headOn[j], point[j], 0.15 * point[j]);
  // The diver's own torch: the ray starts inside the beam, 20 cm in front of the lamp, 3° off its axis.
  const glm::dvec3 tilted = glm::normalize(spot.axis + glm::dvec3(0.0, std::tan(glm::radians(3.0)), 0.0));
  for (double length : {10.0, 1e30}) expectMatches(spot.position + 0.2 * spot.axis, tilted, length, spot, 0.0, kTolerance);
  // Every ray through the scene is finite: from around the lamp, in 2 000 directions.
  for (int i = 0; i < 2000; ++i) {
    const double z = 1.0 - 2.0 * (i + 0.5) / 2000.0, phi = 2.399963 * i;  // a Fibonacci sphere
    const glm::dvec3 dir(std::sqrt(1.0 - z * z) * std::cos(phi), z, std::sqrt(1.0 - z * z) * std::sin(phi));
    for (const glm::dvec3& origin : {spot.position + 0.2 * spot.axis, spot.position - glm::dvec3(0.0, 0.0, 1e-4), camera}) {
      const vec4 got = gpuSide(kSigmaS, kSigmaT, origin, dir, 1e30, spot, 0.0);
      ASSERT_TRUE(!glm::any(glm::isnan(got)) && !glm::any(glm::isinf(got)) && glm::all(glm::greaterThanEqual(got, vec4(0.0f))))
          << i;
    }
  }
  // Pointing away from the ray, it lights none of it.
  spot.axis = -spot.axis;
  EXPECT_EQ(gpuSide(kSigmaS, kSigmaT, camera, {0.0, 0.0, -1.0}, 1e30, spot, 0.0), vec4(0.0f));
}

// Rays nearly along the cone's surface, where its quadratic is ill-conditioned (A = (d·axis)² −
// cos²θ near 0): from 30 cm in front of the lamp on its axis, and parallel to the cone's side
// 1 cm inside and outside it, at angles to the axis either side of the cone's 12°.
TEST(UnderwaterLamps, ARayAlongTheConesSideFindsItsBeam) {
  Lamp spot;
  spot.type = kLightSpot;
  spot.position = {0.0, -5.0, 0.0};
  spot.axis = glm::normalize(glm::dvec3(0.3, -1.0, 0.2));
  spot.cosInner = std::cos(glm::radians(11.0));
  spot.cosOuter = std::cos(glm::radians(12.0));
  const glm::dvec3 side = glm::normalize(glm::cross(spot.axis, glm::dvec3(0.0, 0.0, 1.0)));
  for (double degrees : {10.5, 11.5, 11.9, 11.99, 12.0, 12.01, 12.5}) {
    const double angle = glm::radians(degrees);
    const glm::dvec3 dir = std::cos(angle) * spot.axis + std::sin(angle) * side;
    for (double length : {3.0, 1e30}) expectMatches(spot.position + 0.3 * spot.axis, dir, length, spot, 0.0, kTolerance);
  }
  const double cone = glm::radians(12.0);
  const glm::dvec3 generator = std::cos(cone) * spot.axis + std::sin(cone) * side;
  const glm::dvec3 inward = std::cos(cone) * side - std::sin(cone) * spot.axis;  // normal to the side, out of the cone
  for (double offset : {-0.01, 0.01})
    for (double length : {3.0, 1e30})
      expectMatches(spot.position + 0.5 * generator + offset * inward, generator, length, spot, 0.0, kTolerance);
  // An endless ray 1e-7 rad from the cone's angle that enters the beam 3.1 m along and leaves it
  // 580 km on: in float the quadratic's A rounded to 0, the far cut was lost, and the piece from
  // the near one on, tested at its middle 5e29 m away, where only its direction counts, was taken
  // as outside: the beam gave nothing.
  Lamp grazed;
  grazed.type = kLightSpot;
  grazed.position = {1.2314552, -3.78960805, 1.51261163};
  grazed.axis = {-0.967272146, 0.250492297, -0.0404747352};
  grazed.cosOuter = 0.931072831;
  grazed.cosInner = std::cos(std::acos(grazed.cosOuter) - glm::radians(3.0));
  expectMatches({4.19281885, -3.79949907, 0.725780606}, {-0.969358633, 0.0134411582, 0.24528183}, 1e30, grazed, 0.0,
                kTolerance);
}

// A lamp above the surface reaches the ray through water only over its path's lower part.
TEST(UnderwaterLamps, ALampAboveTheWaterIsDimmedOnlyBelowTheSurface) {
  Lamp lamp;
  lamp.position = {0.0, 3.0, -5.0};
  expectMatches({0.0, -1.0, 0.0}, {0.0, 0.0, -1.0}, 1e30, lamp, 0.0, kTolerance);
  expectMatches({0.0, -1.0, 0.0}, {0.0, 0.4, -1.0}, 1.0 / std::sin(std::atan(0.4)), lamp, 0.0, kTolerance);  // up to the surface
}

// In water that barely attenuates, a lamp h metres beside an endless ray, from its closest point
// on, gives σs/(4π)·I·π/(2h): ∫₀^∞ ds/(h² + s²).
TEST(UnderwaterLamps, ClearWaterGivesTheClosedForm) {
  Lamp lamp;
  lamp.position = {2.0, -5.0, 0.0};
  const vec4 sigmaS(1.0f), sigmaT(1e-9f);
  const vec4 got = gpuSide(sigmaS, sigmaT, {0.0, -5.0, 0.0}, {0.0, 0.0, -1.0}, 1e30, lamp, 0.0);
  for (int j = 0; j < 4; ++j) EXPECT_NEAR(got[j], 1.0 / (4.0 * std::numbers::pi) * std::numbers::pi / (2.0 * 2.0), 1e-6);
}

}  // namespace
}  // namespace prism::shared
