// The closed form of shaders/shared/underwater.glsl against numerical integration of the same
// single-scattering integral, for all ten Jerlov types, looking down, sideways and up.
#include <gtest/gtest.h>

#include <cmath>

#include "core/worst_of.h"
#include "techniques/underwater/jerlov_water.h"
#include "techniques/underwater/underwater_layout.h"

namespace prism::underwater {
namespace {

constexpr double kPi = 3.14159265358979;

// ∫₀^S σs/(4π)·e^(−Kd·(z + w·s))·e^(−σt·s) ds by composite Simpson in double precision.
double numericalInScattering(double sigmaS, double sigmaT, double kd, double depth, double w, double distance) {
  const int steps = 20000;
  double h = distance / steps, sum = 0.0;
  for (int k = 0; k <= steps; ++k) {
    double s = k * h;
    double f = sigmaS / (4.0 * kPi) * std::exp(-kd * (depth + w * s)) * std::exp(-sigmaT * s);
    sum += f * (k == 0 || k == steps ? 1.0 : (k % 2 ? 4.0 : 2.0));
  }
  return sum * h / 3.0;
}

TEST(UnderwaterModel, ClosedFormMatchesNumericalIntegrationForEveryWaterType) {
  const glm::vec4 lambdaNm(412.0f, 488.0f, 555.0f, 680.0f);
  double worst = 0.0;
  for (const std::string& type : listJerlovTypes()) {
    WaterProperties water = jerlovWater(type);
    glm::vec4 sigmaS, sigmaT, kd;
    for (int j = 0; j < 4; ++j) {
      sigmaS[j] = static_cast<float>(water.sigmaS.at(lambdaNm[j]));
      sigmaT[j] = static_cast<float>(water.sigmaA.at(lambdaNm[j]) + water.sigmaS.at(lambdaNm[j]));
      kd[j] = static_cast<float>(water.kd.at(lambdaNm[j]));
    }
    for (float depth : {1.0f, 10.0f, 50.0f}) {
      for (float w : {1.0f, 0.5f, 0.0f, -0.5f, -1.0f}) {    // down, oblique, level, up
        for (float distance : {0.5f, 5.0f, 40.0f}) {
          if (depth + w * distance < 0.0f) continue;       // the ray would leave the water
          glm::vec4 closed = shared::waterInScattering(sigmaS, sigmaT, kd, depth, w, distance);
          for (int j = 0; j < 4; ++j) {
            double numeric = numericalInScattering(sigmaS[j], sigmaT[j], kd[j], depth, w, distance);
            // Coastal water at 50 m leaves e^(−200) of the violet light: below float's normal
            // range (1.2e-38), where no float formula has relative precision. Those must be ~0.
            if (numeric < 1e-30) {
              EXPECT_LT(closed[j], 1e-30f) << type << " depth " << depth;
              continue;
            }
            double relative = std::abs(closed[j] - numeric) / numeric;
            worst = worstOf(worst, relative);
            EXPECT_LT(relative, 1e-3) << type << " depth " << depth << " w " << w << " S " << distance
                                      << " λ " << lambdaNm[j];
          }
        }
      }
    }
  }
  std::printf("closed form vs numerical integration, 10 types × 4 λ × depths, directions, distances: max relative %.2e\n", worst);
}

TEST(UnderwaterModel, TheSeriesTakesOverWhereTheClosedFormIsZeroOverZero) {
  // Kd·w + σt = 0 exactly: the integrand is constant, the integral σs·e^(−Kd·z)/(4π)·S.
  glm::vec4 sigmaS(0.1f), sigmaT(0.5f), kd(0.5f);
  glm::vec4 v = shared::waterInScattering(sigmaS, sigmaT, kd, 2.0f, -1.0f, 1.5f);
  double expected = 0.1 * std::exp(-0.5 * 2.0) / (4.0 * kPi) * 1.5;
  EXPECT_NEAR(v.x / expected, 1.0, 1e-6);
  EXPECT_TRUE(std::isfinite(v.x));
}

// Looking up through strongly attenuating water (a user's `--set water.kd_scale=50` on the reef):
// x = Kd·w + σt < 0 and e^(−xS) alone overflows float, which made 614 of 3 600 pixels NaN
// (∞ times e^(−Kd·z_c) = 0). The integral itself is small and finite.
TEST(UnderwaterModel, LookingUpThroughDarkWaterStaysFinite) {
  for (float kdValue : {2.0f, 20.0f, 60.0f}) {
    glm::vec4 sigmaS(0.05f), sigmaT(0.1f), kd(kdValue);
    for (float depth : {10.0f, 30.0f})
      for (float distance : {5.0f, 9.9f}) {  // straight up (w = −1), the end still under water
        glm::vec4 v = shared::waterInScattering(sigmaS, sigmaT, kd, depth, -1.0f, distance);
        const double numeric = numericalInScattering(0.05, 0.1, kdValue, depth, -1.0, distance);
        ASSERT_TRUE(std::isfinite(v.x)) << "Kd " << kdValue << " depth " << depth << " S " << distance;
        if (numeric < 1e-30) {
          EXPECT_LT(v.x, 1e-30f);
        } else {
          EXPECT_LT(std::abs(v.x - numeric) / numeric, 1e-3) << "Kd " << kdValue << " depth " << depth << " S " << distance;
        }
      }
  }
}

// A ray that leaves the water at its surface ends at depth 0, its exponent −Kd·0 − σt·S; in float
// z_c + w·S rounds a little above the surface, which times Kd = 5e7/m (a scene's kd_scale of 1e9)
// overflowed to inf.
TEST(UnderwaterModel, ARayEndingAtTheSurfaceStaysFiniteUnderAnyKd) {
  for (float kdValue : {5e4f, 5e7f, 5e8f, 5e10f}) {  // without the clamp 9 of these 100 cases overflowed
    const glm::vec4 sigmaS(0.05f), sigmaT(0.1f), kd(kdValue);
    for (float depth : {0.3f, 1.0f, 7.0f, 13.0f, 30.0f})
      for (float up : {0.31f, 0.5f, 0.7f, 0.83f, 0.97f}) {
        const glm::vec4 v = shared::waterInScattering(sigmaS, sigmaT, kd, depth, -up, depth / up);
        EXPECT_TRUE(std::isfinite(v.x) && v.x >= 0.0f) << "Kd " << kdValue << " depth " << depth << " up " << up;
      }
  }
}

TEST(UnderwaterModel, TransmittanceAndDownwellingAreBeerLambert) {
  glm::vec4 t = shared::waterTransmittance(glm::vec4(0.1f, 0.2f, 0.0f, 1.0f), 3.0f);
  EXPECT_NEAR(t.x, std::exp(-0.3), 1e-6);
  EXPECT_NEAR(t.z, 1.0, 1e-7);
  glm::vec4 e = shared::downwellingAttenuation(glm::vec4(0.05f), -2.0f);  // above the surface
  EXPECT_FLOAT_EQ(e.x, 1.0f);
}

TEST(UnderwaterModel, ALampsPathIsUnderWaterBelowTheSurfaceOnly) {
  EXPECT_FLOAT_EQ(shared::shareBelowSurface(-3.0f, -1.0f, 0.0f), 1.0f);  // both below
  EXPECT_FLOAT_EQ(shared::shareBelowSurface(1.0f, 4.0f, 0.0f), 0.0f);    // both above
  EXPECT_FLOAT_EQ(shared::shareBelowSurface(-2.0f, 8.0f, 0.0f), 0.2f);   // 2 m of 10 below
  EXPECT_FLOAT_EQ(shared::shareBelowSurface(8.0f, -2.0f, 0.0f), 0.2f);   // either way round
  EXPECT_FLOAT_EQ(shared::shareBelowSurface(-1.0f, -1.0f, -1.0f), 1.0f); // level, at the surface
}

}  // namespace
}  // namespace prism::underwater
