// Everything about how a frame is rendered that is not the scene: resolution, mode, wavelength
// sampling, observer, display transform. All of it can change between frames without a restart
// (the renderer rebuilds only what a change needs). The text form of every field users set
// (names, parsing, printing, help) is render/setting_keys.h's table; each enum's names are here.
#pragma once

#include <optional>
#include <string>
#include <string_view>

#include "spectral/colour_space.h"
#include "spectral/sampling.h"

namespace prism::render {

// rgb: three channels as "wavelengths" (the common practice); naive: box upsampling at
// 495/570 nm; jakob-hanika: sigmoid upsampling with `sampling`; reference: Jakob–Hanika with
// kReferenceWavelengths uniform wavelengths over 360–830 nm, whatever `sampling` says;
// optimised4: Jakob–Hanika at the sky's four optimised wavelengths with their weights
// (data/atmosphere_wavelengths.json, the set of the scene's atmosphere; García Liñán).
enum class RenderMode { Rgb, Naive, JakobHanika, Reference, Optimised4 };
std::string_view renderModeName(RenderMode mode);

inline constexpr int kReferenceWavelengths = 472;  // ≈ 1 nm steps over 360–830 nm

enum class ToneMap { None, Reinhard, Aces };
std::string_view toneMapName(ToneMap toneMap);

// Where the Jakob–Hanika coefficients come from: the manual eight-fetch blend (bit-identical to
// the CPU) or one hardware-filtered fetch (faster, an equally smooth interpolant).
enum class UpsamplingLookup { Manual, Filtered };
std::string_view upsamplingLookupName(UpsamplingLookup lookup);

// What the G-buffer keeps of a base colour: its RGB (upsampled once per pixel by the lighting
// pass) or its Jakob–Hanika coefficients (looked up per G-buffer fragment, one RGBA32F target
// more). Issue #4 asked which is faster; `prism bench` measures both side by side.
enum class GBufferAlbedo { Rgb, Coefficients };
std::string_view gbufferAlbedoName(GBufferAlbedo albedo);

// The display transform's settings: all a caller needs to show tristimulus values (a reference
// image, say) the way the renderer's post pass would, without the rest of a frame's settings.
struct DisplaySettings {
  std::optional<float> ev100;            // overrides the scene camera's exposure
  std::string whiteBalance = "none";     // an illuminant name (e.g. "A") adapted to the display white
  Adaptation adaptation = Adaptation::Bradford;
  ToneMap toneMap = ToneMap::Aces;
  std::string colourSpace = "srgb";      // srgb | display-p3 | rec2020 (transfer included)
  bool dither = true;                    // before 8-bit quantisation
};

struct FrameSettings {
  int width = 1280;
  int height = 720;
  RenderMode mode = RenderMode::JakobHanika;
  // Spectral modes other than reference. The default, 16 wavelengths fitted for the scene's
  // lights (spectral/wavelength_fit.h), is the best one frame measured in every example scene
  // (README, "Optimised wavelength sets"): as close as 200 uniform wavelengths.
  SamplingSettings sampling{16, kLambdaMinNm, kLambdaMaxNm, SamplingStrategy::Optimised};
  std::string observer = "cie1931";   // or a camera from data/cameras.csv: raw camera RGB
  UpsamplingLookup lookup = UpsamplingLookup::Filtered;
  GBufferAlbedo gbufferAlbedo = GBufferAlbedo::Rgb;
  int shadowMapSize = 2048;
  // A directional light's shadow maps: 1 covers the whole scene; more are fitted to the camera's
  // view, finest near it (render/shadow_views.h), up to kShadowCascadesMax. Four: one default
  // frame of the example spheres is twice as close to the path tracer (README, "A directional
  // light's cascades").
  int shadowCascades = 4;
  bool lightGizmos = false;  // forward pass: an emissive marker at each point and spot light
  DisplaySettings display;
};

constexpr int kShadowCascadesMax = 4;  // shared::kMaxShadowCascades, the GPU's light record's room

// Error naming the setting for sizes, counts and names out of range.
void validate(const FrameSettings& settings);
void validate(const DisplaySettings& settings);
// Error unless the exposure lies within ±kEv100Limit (scene/scene.h).
void validateEv100(float ev100);

// The wavelength sampling the mode actually uses (RGB and optimised4 use none: uniform, unused).
SamplingSettings effectiveSampling(const FrameSettings& settings);

// Whether successive frames of a still scene differ — their wavelengths are the only thing drawn
// per frame — so that accumulating them converges: not in rgb, optimised4 or reference mode, nor
// with the uniform or optimised strategy.
bool framesDiffer(const FrameSettings& settings);

// Whether the mode renders with `sampling`'s wavelengths (naive, jakob-hanika); rgb, optimised4
// and reference ignore the count, range and strategy.
bool usesSampling(RenderMode mode);

}  // namespace prism::render
