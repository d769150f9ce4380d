// The metamer generator: a match under one illuminant, a mismatch as large as possible under
// another, a reflectance all the same.
#include <gtest/gtest.h>

#include "core/error.h"
#include "spectral/colour_checker.h"
#include "spectral/illuminant.h"
#include "techniques/prt/metamer.h"
#include "techniques/prt/prt_spectra.h"

namespace prism::prt {
namespace {

TEST(Metamer, MatchesUnderD65AndDiffersUnderA) {
  // The bounds: ΔE00 ≤ 0.5 under D65, ≥ 5 under A; F2 reported. Patches across the
  // chart: a skin tone, a saturated blue, a grey.
  const Observer& obs = cie1931Observer();
  Spectrum d65 = illuminant("D65"), a = illuminant("A"), f2 = illuminant("F2");
  for (int patch : {1, 12, 21}) {
    const ColourCheckerPatch& p = colourChecker()[static_cast<std::size_t>(patch)];
    Metamer m = findMetamer(p.reflectance, d65, a, obs);
    double underD65 = reflectanceDeltaE2000(p.reflectance, m.reflectance, d65, obs);
    double underA = reflectanceDeltaE2000(p.reflectance, m.reflectance, a, obs);
    double underF2 = reflectanceDeltaE2000(p.reflectance, m.reflectance, f2, obs);
    std::printf("%-14s ΔE00 D65 %.4f  A %.3f  F2 %.3f\n", p.name.c_str(), underD65, underA, underF2);
    EXPECT_LE(underD65, 0.5) << p.name;
    EXPECT_GE(underA, 5.0) << p.name;
    EXPECT_NEAR(m.targetDeltaE2000, underA, 1e-9);
    EXPECT_GE(m.gridValues.minCoeff(), 0.0);
    EXPECT_LE(m.gridValues.maxCoeff(), 1.0);
  }
}

TEST(Metamer, RefusesANonReflectance) {
  EXPECT_THROW(findMetamer(Spectrum::constant(1.5), illuminant("D65"), illuminant("A"), cie1931Observer()), Error);
  // A dark illuminant has no colour to match or to differ.
  Spectrum grey = Spectrum::constant(0.5), dark;
  EXPECT_THROW(findMetamer(grey, dark, illuminant("A"), cie1931Observer()), Error);
  EXPECT_THROW(findMetamer(grey, illuminant("D65"), dark, cie1931Observer()), Error);
}

}  // namespace
}  // namespace prism::prt
