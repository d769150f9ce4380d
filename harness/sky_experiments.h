// `prism atmosphere evaluate|optimise`: the wavelength strategies of the spectral sky against
// the 1 nm reference (techniques/atmosphere/sky_evaluation.h), and the offline fit of the four
// optimised wavelengths (wavelength_optimiser.h) into data/atmosphere_wavelengths.json.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace prism::harness {

struct AtmosphereCommandOptions {
  // Unset: a 1 nm reference and 16 × 32 view directions (zeniths × azimuths over the upper
  // hemisphere), or with quick 10 nm and 8 × 16; what is set wins over quick.
  std::optional<double> referenceStepNm;
  std::optional<int> zeniths, azimuths;
  bool aerosols = true;  // evaluate: the atmosphere (and optimised set) with or without aerosols
  bool json = false;
  bool quick = false;    // 10 nm reference, 8 × 16 directions (seconds, for tests)
  std::optional<std::filesystem::path> wavelengths;  // evaluate: a wavelength file other than data/'s
  std::filesystem::path output;       // optimise: where to write (required; the shipped fit is data/atmosphere_wavelengths.json)
};

// The sky the options ask for: what was given, else the full or the quick defaults. Error for
// directions outside 1..512 × 1..1024.
struct SkyRun {
  double referenceStepNm;
  int zeniths, azimuths;
};
SkyRun skyRunOf(const AtmosphereCommandOptions& options);

// Exit status 1 when the optimised set's mean ΔE00 exceeds 1.0 at some elevation (the goal).
int runAtmosphereEvaluate(const AtmosphereCommandOptions& options);
void runAtmosphereOptimise(const AtmosphereCommandOptions& options);

}  // namespace prism::harness
