// Light sources by name, as dense spectra (relative spectral power).
//
// Names (case-sensitive, as `prism colour list illuminants` prints them):
//   A, D65, D50, D55, D75          CIE standard / tabulated daylight illuminants
//   F1 … F12                       CIE fluorescent (CIE 15:2004 5 nm tables)
//   LED-B1 … LED-V2                CIE LED illuminants (CIE 015:2018)
//   led-globe-a19                  the thesis's domestic LED lamp (LSPDD)
//   nist:<lamp>                    NIST CQS / RIT lamp set, e.g. "nist:Cool White FL"
//   daylight:<K>                   CIE daylight D-series at a correlated colour temperature
//   blackbody:<K>                  Planckian radiator, 500–10⁶ K
//   led:<peak nm>:<width nm>       parametric narrow-band LED (Ohno 2005)
// Each SPD keeps the normalisation stated in its IlluminantInfo: Prism never renormalises a
// published table silently; renderers scale lights by their own physical intensity.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "spectral/spectrum.h"

namespace prism {

struct IlluminantInfo {
  std::string name;
  std::string normalisation;
};

Spectrum illuminant(std::string_view name);
std::vector<IlluminantInfo> listIlluminants();

// A lamp a user names: an illuminant's name, or a spectrum file when it ends in .csv (readLampCsv).
Spectrum lampSpectrum(const std::string& nameOrFile);

// CIE 15:2004 §3.1: daylight of a correlated colour temperature in 4000–25000 K, from the
// S0, S1, S2 components; 100 at 560 nm.
Spectrum daylight(double cctK);

// Blackbody scaled to 100 at 560 nm (the CIE convention for illuminant A); Error outside 500–10⁶ K.
Spectrum blackbodyIlluminant(double temperatureK);

// A single-colour LED after Ohno 2005, "Spectral design considerations for white LED color
// rendering", Opt. Eng. 44(11), Eq. 1: S(λ) = (g + 2g⁵)/3, g = exp(−((λ − λ0)/Δλ0.5)²), with
// Δλ0.5 Ohno's "half spectral width" (widthNm). Peak 1 at λ0; the FWHM of S is 0.921·Δλ0.5
// (S = ½ where g = 0.8087).
Spectrum narrowbandLed(double peakNm, double widthNm);

}  // namespace prism
