// The reference renderer: a CPU spectral path tracer over the same scene files, materials and
// formulas as the rasteriser (shaders/shared/brdf.glsl, lights.glsl, surface_inputs.glsl,
// sigmoid.glsl), with rays traced by Embree. It is the ground truth the real-time path is held to.
//
// Estimator. Each path carries four hero wavelengths (Wilkie et al. 2014) drawn as one
// stratified batch over [λmin, λmax] (by default importance-sampled by the observer's
// x̄ + ȳ + z̄; with the Lights strategy by the scene's emission × the observer's curves, the
// rasteriser's pdf: spectral/sampling.h, scene/scene_emission.h) with their pdfs, path s of a pixel's N in part s of each of
// the four strata (so the N paths together stratify the spectrum 4·N ways); its radiance at them goes to tristimulus
// through that batch's integration matrix (observer or camera curves / (4·pdf), times
// absoluteTristimulusScale), so every path is an unbiased estimate of the pixel's XYZ in cd/m².
// Albedos are upsampled with the scene colour space's Jakob–Hanika table (manual lookup, the
// reference path) and evaluated at the wavelengths exactly; measured reflectances and conductors'
// n, k are evaluated at them as tabulated.
//
// Light transport.
// - Direct: what the rasteriser computes. At the first hit, every light (directional, point,
//   spot: delta lights) by next-event estimation with an exact shadow ray for lights that cast
//   shadows (point lights included, which the rasteriser cannot shadow yet: it has no cube
//   maps); a camera ray that escapes sees the background. The only noise is the wavelengths'
//   (and the pixel footprint's with the box filter).
// - Global: paths continue by sampling the BRDF (cosine-weighted for the diffuse lobe, GGX
//   normals for the specular one, combined by their one-sample mixture pdf), next-event
//   estimation at every vertex, Russian roulette from the fourth vertex; rays that escape see the
//   background as uniform surrounding radiance. Delta lights cannot be hit, so nothing is
//   counted twice.
// - Media (Scene::water below its surface, isotropic as the analytic model assumes; else
//   Scene::medium, homogeneous, in a box or everywhere): free flights drawn against
//   scattering with spectral MIS over the four wavelengths, absorption as Beer–Lambert weight,
//   Henyey–Greenstein phase; next-event estimation at every scattering event and surface with
//   the medium's transmittance on the shadow ray: multiple scattering. Direct is single
//   scattering: each path scatters once at a distance drawn from the extinction (truncated to
//   the segment, spectral MIS) and also reaches the surface behind it through the exact
//   transmittance, both lit by the lights.
#pragma once

#include <cstdint>
#include <functional>
#include <string>
#include <string_view>

#include "imaging/float_image.h"
#include "scene/scene.h"
#include "spectral/rgb_to_spectrum_table.h"
#include "spectral/sampling.h"

namespace prism::reference {

enum class LightTransport { Direct, Global };
LightTransport lightTransportFromName(std::string_view name);  // direct|global

// Box: each sample at a uniformly random point of the pixel (antialiased). Centre: every sample
// at the pixel's centre, as a rasteriser samples, so that an image compared with one differs only
// in what is computed there, not in where.
enum class PixelFilter { Box, Centre };
PixelFilter pixelFilterFromName(std::string_view name);  // box|centre

struct ReferenceSettings {
  int width = 640;
  int height = 360;
  int samplesPerPixel = 64;  // paths per pixel, 4 wavelengths each
  LightTransport transport = LightTransport::Direct;
  int maxDepth = 16;         // global: interactions per path at most (surface hits and scattering events)
  PixelFilter filter = PixelFilter::Box;
  std::string observer = "cie1931";  // or a camera: raw camera RGB (on the luminance scale)
  // The hero wavelengths: count must be 4. Importance (the observer's response) by default;
  // Lights follows the scene's emission as well.
  SamplingSettings wavelengths{4, kLambdaMinNm, kLambdaMaxNm, SamplingStrategy::Importance};
  std::uint32_t seed = 0;    // the image is a deterministic function of the seed and settings
  unsigned threads = 0;      // 0: all hardware threads (the image does not depend on it)
};

// Error naming the setting when out of range.
void validate(const ReferenceSettings& settings);

struct ReferenceImage {
  imaging::FloatImage tristimulus;  // mean over the pixel's paths, 3 channels, row 0 at the top
  // The variance of that mean per channel: sample variance / N, an upper bound for the
  // stratified wavelengths.
  imaging::FloatImage variance;
};

// done / total in pixel rows × passes; called from one thread at a time.
using ReferenceProgress = std::function<void(std::size_t done, std::size_t total)>;

// `table` is the Jakob–Hanika table of the scene's colour space.
ReferenceImage renderReference(const Scene& scene, const RgbToSpectrumTable& table,
                               const ReferenceSettings& settings,
                               const ReferenceProgress& progress = {});

}  // namespace prism::reference
