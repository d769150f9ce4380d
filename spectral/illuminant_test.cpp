#include "spectral/illuminant.h"

#include <gtest/gtest.h>

#include <cmath>

#include "spectral/colour_space.h"
#include "core/error.h"
#include "spectral/observer.h"

namespace prism {
namespace {

TEST(Illuminant, D65WhitePointAt1nm) {
  Chromaticity xy = xyzToXy(observer("cie1931").integrate(illuminant("D65")));
  EXPECT_NEAR(xy.x, 0.3127, 1e-4);
  EXPECT_NEAR(xy.y, 0.3290, 1e-4);
}

TEST(Illuminant, AWhitePoint) {
  // CIE 15:2004 Table T.3: A (2°) x = 0.44757, y = 0.40745.
  Chromaticity xy = xyzToXy(observer("cie1931").integrate(illuminant("A")));
  EXPECT_NEAR(xy.x, 0.44757, 1e-4);
  EXPECT_NEAR(xy.y, 0.40745, 1e-4);
}

TEST(Illuminant, D50WhitePoint) {
  // CIE 15:2004 Table T.3: D50 (2°) x = 0.34567, y = 0.35850.
  Chromaticity xy = xyzToXy(observer("cie1931").integrate(illuminant("D50")));
  EXPECT_NEAR(xy.x, 0.34567, 2e-4);
  EXPECT_NEAR(xy.y, 0.35850, 2e-4);
}

TEST(Illuminant, Daylight6504MatchesTabulatedD65Within1Percent) {
  Spectrum computed = daylight(6504.0);
  Spectrum tabulated = illuminant("D65");
  for (int l = 380; l <= 780; ++l)
    EXPECT_NEAR(computed.at(l), tabulated.at(l), 0.01 * tabulated.at(l)) << l << " nm";
}

TEST(Illuminant, DaylightByNameEqualsDaylightFunction) {
  Spectrum a = illuminant("daylight:5003");
  Spectrum b = daylight(5003.0);
  for (int i = 0; i < kSpectrumSamples; ++i) EXPECT_EQ(a[i], b[i]);
}

TEST(Illuminant, DaylightOutsideItsDomainIsAnError) {
  EXPECT_THROW(daylight(3000.0), Error);
  EXPECT_THROW(illuminant("daylight:30000"), Error);
}

TEST(Illuminant, BlackbodyAt2856KIsIlluminantA) {
  // A is a Planckian radiator at 2848 K with the old c2 = 1.435e-2 m·K, i.e. 2856 K today.
  Spectrum bb = illuminant("blackbody:2856");
  Spectrum a = illuminant("A");
  for (int l = 380; l <= 780; l += 10) EXPECT_NEAR(bb.at(l), a.at(l), 0.002 * a.at(l)) << l;
  EXPECT_NEAR(bb.at(560), 100.0, 1e-9);
}

TEST(Illuminant, NarrowbandLedPeaksAtItsWavelengthWithItsWidth) {
  Spectrum led = illuminant("led:450:20");
  EXPECT_NEAR(led.at(450), 1.0, 1e-12);
  // Half maximum where g + 2g⁵ = 1.5, i.e. g = 0.8087: 0.4607 × 20 nm = 9.2 nm from the peak.
  double halfLeft = 0.0;
  for (double l = 400.0; l < 450.0; l += 0.01)
    if (led.at(l) < 0.5) halfLeft = l;
  EXPECT_GT(450.0 - halfLeft, 8.0);
  EXPECT_LT(450.0 - halfLeft, 10.0);
  EXPECT_LT(led.at(390), 1e-4);  // g = e⁻⁹ three widths away
}

TEST(Illuminant, EveryListedNameLoads) {
  for (const IlluminantInfo& info : listIlluminants()) {
    if (info.name.find('<') != std::string::npos) continue;  // parametric forms
    Spectrum s = illuminant(info.name);
    EXPECT_GT(s.integral(), 0.0) << info.name;
    EXPECT_FALSE(info.normalisation.empty()) << info.name;
  }
}

TEST(Illuminant, ThesisLedAndNistLampsAreThere) {
  EXPECT_GT(illuminant("led-globe-a19").maxValue(), 0.0);
  EXPECT_GT(illuminant("nist:Cool White FL").maxValue(), 0.0);
  EXPECT_GT(illuminant("F11").maxValue(), 0.0);
  EXPECT_GT(illuminant("LED-B3").maxValue(), 0.0);
}

TEST(Illuminant, UnknownNamesAreErrorsNamingThem) {
  for (const char* name : {"D66", "nist:Nothing", "led:450", "blackbody:hot", "led:abc:20"}) {
    try {
      illuminant(name);
      ADD_FAILURE() << name;
    } catch (const Error& e) {
      EXPECT_NE(std::string(e.what()).find(name), std::string::npos) << e.what();
    }
  }
}

}  // namespace
}  // namespace prism
