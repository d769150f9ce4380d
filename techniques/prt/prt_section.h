// The scene file's "prt" section (docs/scene-format.md, "PRT"): the distant spectral environment
// that lights the scene's PRT objects (objects whose `technique` is "prt"), the spectral basis
// size and the mode — spectral PRT (Schwenk, Kuijper & Bockholt), RGB-PRT or the 5 nm reference,
// all three through the same transfer and the same run-time sums (prt_evaluation.h). The
// renderer draws PRT objects in the PRT forward pass (gpu/prt_pass.h); this half holds no
// OpenGL. Units: the environment's radiance is scaled so that `luminanceCdM2` is its luminance
// (zenith for the sky gradient, everywhere for uniform, a (1, 1, 1) texel for a map), making the
// objects' XYZ absolute like the rest of the frame (Y in cd/m²).
#pragma once

#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "imaging/float_image.h"
#include "spectral/rgb_to_spectrum_table.h"
#include "techniques/prt/prt_evaluation.h"
#include "techniques/prt/prt_sky.h"
#include "techniques/technique_section.h"

namespace prism::prt {

enum class PrtMode { Spectral, RgbPrt, Reference5nm };
std::string_view prtModeName(PrtMode mode);  // "spectral", "rgb-prt", "reference-5nm"

// An equirectangular map as read (linear sRGB, row 0 at the zenith), shared between copies.
struct PrtMap {
  std::filesystem::path file;
  int width = 0, height = 0;
  std::vector<float> linearRgb;  // width × height RGB triples
};

struct PrtSection final : TechniqueSection {
  static constexpr std::string_view kKey = "prt";

  std::string illuminant = "D65";                 // a name as `prism colour list illuminants` prints
  std::string shape = "sky";                      // "sky" (CIE overcast gradient) or "uniform"
  std::shared_ptr<const PrtMap> map;              // instead of illuminant and shape, when given
  std::optional<PrtSky> sky;                      // Prism's spectral sky instead of either (absolute: no luminance)
  float luminanceCdM2 = 1000.0f;
  float rotationDeg = 0.0f;                       // about the zenith (world +y), counter-clockwise seen from above
  int basis = 8;                                  // m, 1..16 (spectral mode)
  PrtMode mode = PrtMode::Spectral;
  int samples = 256;                              // transfer directions per vertex, 1..2²⁰
  bool shadows = true;                            // self-shadowing in the transfer

  std::string_view key() const override { return kKey; }
  std::string_view shaderDefine() const override { return "PRISM_TECHNIQUE_PRT"; }
  std::unique_ptr<TechniqueSection> clone() const override { return std::make_unique<PrtSection>(*this); }
  // No block: the forward pass uploads what it draws when the section changes.
  TechniqueBlock pack(const FramePackInput& input) const override;
  // Under the spectral sky with its disc, the sun as a light of the scene: the solar irradiance
  // that reaches the ground (the grid's, 380–780 nm, 0 outside), from the sun's direction turned
  // with the environment, following the section. The lighting pass lights every object by it
  // (PRT's too, with shadow maps), the reference traces it as a light; the environment itself
  // holds the sky alone.
  std::optional<TechniqueLight> light() const override;
  // The environment as radiance per direction, for the reference path tracer (prt_environment_radiance.h).
  std::shared_ptr<const TechniqueEnvironment> environment(const RgbToSpectrumTable& table) const override;
  // The environment map's size and texels, when there is one.
  std::uint64_t hashLoadedData(std::uint64_t hash) const override;
  std::vector<std::filesystem::path> inputFiles() const override;  // the map's, when there is one
  // Spectral PRT with m = 8 against RGB-PRT, both on this scene in a frame of 16 wavelengths, the
  // PRT pass timed in each.
  TechniqueBench bench(std::size_t pointAndSpotLights) const override;
  bool shadesObjects() const override { return true; }
  // RGB-PRT's under any observer but CIE 1931 (requireRgbPrtObserver); the reference mode's frame
  // draws the 5 nm reference whatever the mode.
  void requireObserver(const Observer& observer, bool referenceMode) const override;

  static std::unique_ptr<TechniqueSection> parse(const schema::Node& node, const TechniqueSections& earlier);
};

// An equirectangular environment map as linear sRGB, row 0 at the zenith: a Radiance .hdr (by
// its extension; the format names no primaries, and maps for rendering are made in these) or an
// OpenEXR file whose colour is linear sRGB. Error "FILE: …" on one line otherwise.
imaging::FloatImage readEnvironmentMap(const std::filesystem::path& file);

// ∫ S ȳ dλ on PRT's 5 nm grid (CIE 1931): the scale that makes a spectrum's luminance 1 cd/m²
// once 683 lm/W is folded into it (PRT's XYZ carry no 683 of their own).
double gridLuminance(const Spectrum& spd);
// An environment's illuminant by name: Error naming it when unknown, or when less than
// kMinGridLuminanceShare of its luminance lies on PRT's 380–780 nm grid, where it is scaled.
inline constexpr double kMinGridLuminanceShare = 0.9;
Spectrum environmentIlluminant(const std::string& name);

// The section's environment, z-up (PRT's convention), turned by rotationDeg about the zenith and
// scaled to its luminance (the spectral sky: absolute, 683 lm/W folded in as PRT's spectra carry
// it); srgbTable upsamples a map's texels (the unbounded intent). The spectral sky's sun (when
// sun_disc) is the renderer's light (PrtSection::light), so the environment holds the sky alone;
// with `sunInEnvironment` (what has no lights: `prt report`) it holds the sun too, on SH-5.
SpectralEnvironment sectionEnvironment(const PrtSection& section, const RgbToSpectrumTable& srgbTable,
                                       bool sunInEnvironment = false);

// What the section's environment is made from, as text: equal keys, the same environment.
std::string environmentKey(const PrtSection& section);

// The sky's grid, tabulated once per change of its atmosphere or sun (the last one is kept:
// rotating the environment, hiding the sun's disc or changing the mode or basis does not
// tabulate it again).
std::shared_ptr<const SkyRadianceGrid> sectionSky(const PrtSky& sky);

}  // namespace prism::prt
