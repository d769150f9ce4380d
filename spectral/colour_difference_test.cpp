#include "spectral/colour_difference.h"

#include <gtest/gtest.h>

#include <cmath>

#include "core/csv.h"
#include "core/data_files.h"
#include "core/error.h"

namespace prism {
namespace {

TEST(Ciede2000, AgreesWithSharmaWuDalalTestData) {
  CsvTable t = CsvTable::read(dataFile("ciede2000_sharma.csv"));
  ASSERT_EQ(t.rows().size(), 34u);
  for (const CsvRow& row : t.rows()) {
    Eigen::Vector3d lab1(t.number(row, 1), t.number(row, 2), t.number(row, 3));
    Eigen::Vector3d lab2(t.number(row, 4), t.number(row, 5), t.number(row, 6));
    double expected = t.number(row, 7);
    EXPECT_NEAR(deltaE(lab1, lab2, DeltaEFormula::Ciede2000), expected, 1e-4) << "pair " << row.fields[0];
    EXPECT_NEAR(deltaE(lab2, lab1, DeltaEFormula::Ciede2000), expected, 1e-4) << "pair " << row.fields[0];
  }
}

// Beyond C ≈ 3e5, C⁷ overflowed float: ΔE00 came out inf or NaN (a pixel 1e15 times its white
// in `compare`, `colour delta-e --lab 1e6,1e6,1e6`). Far from the locus the chroma weight is 1, so
// the difference of two colours there is finite and, scaled up together, grows in proportion.
TEST(Ciede2000, StaysFiniteForHugeChroma) {
  for (double scale : {1e6, 1e9, 1e12}) {
    Eigen::Vector3d a(scale, scale, scale), b(0.0, 0.0, 0.0), c(scale, 1.01 * scale, scale);
    const double far = deltaE(a, b, DeltaEFormula::Ciede2000), near = deltaE(a, c, DeltaEFormula::Ciede2000);
    EXPECT_TRUE(std::isfinite(far) && far > 0.0) << scale << ": " << far;
    EXPECT_TRUE(std::isfinite(near) && near > 0.0 && near < far) << scale << ": " << near;
  }
}

TEST(DeltaE, Cie76And94OnAKnownPair) {
  // Worked by hand: ΔE*ab = √(405.107² + 199.832²); ΔE*94 with graphic-arts weights.
  Eigen::Vector3d a(100.0, 21.57210357, 272.2281935), b(100.0, 426.67945353, 72.39590835);
  EXPECT_NEAR(deltaE(a, b, DeltaEFormula::Cie76), 451.7133019, 1e-3);
  EXPECT_NEAR(deltaE(a, b, DeltaEFormula::Cie94), 83.7792255, 1e-3);
  EXPECT_EQ(deltaE(a, a, DeltaEFormula::Cie94), 0.0);
}

TEST(Cielab, WhiteIsL100AndRoundTrips) {
  Eigen::Vector3d white(0.95047, 1.0, 1.08883);
  EXPECT_TRUE(xyzToLab(white, white).isApprox(Eigen::Vector3d(100.0, 0.0, 0.0), 1e-6));
  for (Eigen::Vector3d xyz : {Eigen::Vector3d(0.2, 0.3, 0.1), Eigen::Vector3d(0.001, 0.002, 0.004)})
    EXPECT_TRUE(labToXyz(xyzToLab(xyz, white), white).isApprox(xyz, 1e-5)) << xyz.transpose();
}

// Under a light with no Z at all (a 700 nm line) the white's Z is taken at 1e-6 of its Y: a* and
// b* were NaN (`colour xyz --illuminant led:700:0.01` printed "Lab 76 0 -nan").
TEST(Cielab, AWhiteMissingAChannelGivesFiniteLab) {
  const Eigen::Vector3d white(0.73, 0.27, 0.0);
  const Eigen::Vector3d lab = xyzToLab(0.5 * white, white);
  EXPECT_TRUE(lab.allFinite()) << lab.transpose();
  EXPECT_NEAR(lab.x(), 76.06, 0.01);
  EXPECT_NEAR(labWhite(white).z(), 2.7e-7, 1e-14);  // in double (the GPU's: cielab_parity_test)
  EXPECT_TRUE(labToXyz(lab, white).allFinite());
}

TEST(DeltaE, FormulaNames) {
  EXPECT_EQ(deltaEFormulaFromName("94"), DeltaEFormula::Cie94);
  EXPECT_THROW(deltaEFormulaFromName("1976"), Error);
}

}  // namespace
}  // namespace prism
