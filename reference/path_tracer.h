// The reference renderer: a CPU spectral path tracer over the same scene files, materials and
// formulas as the rasteriser (shaders/shared/brdf.glsl, lights.glsl, surface_inputs.glsl,
// sigmoid.glsl), with rays traced by Embree. It is the ground truth the real-time path is held to.
//
// Estimator. Each path carries four hero wavelengths (Wilkie et al. 2014) drawn as one
// stratified batch over [λmin, λmax] (by default, the Lights strategy, importance-sampled by the
// scene's emission × the observer's curves, the rasteriser's pdf: spectral/sampling.h,
// scene/scene_emission.h; Importance by the observer's x̄ + ȳ + z̄ alone) with their pdfs, path s of a pixel's N in part s of each of
// the four strata (so the N paths together stratify the spectrum 4·N ways); its radiance at them goes to tristimulus
// through that batch's integration matrix (observer or camera curves / (4·pdf), times
// absoluteTristimulusScale), so every path is an unbiased estimate of the pixel's XYZ in cd/m².
// Albedos are upsampled with the scene colour space's Jakob–Hanika table (manual lookup, the
// reference path) and evaluated at the wavelengths exactly; measured reflectances and conductors'
// n, k are evaluated at them as tabulated, spectral textures filtered bilinearly at the hit's uv.
//
// Light transport.
// - Direct: what the rasteriser computes. At the first hit, every light (directional, point,
//   spot: delta lights) by next-event estimation with an exact shadow ray for lights that cast
//   shadows (the rasteriser's shadow maps are PCF-soft); a camera ray that escapes sees the
//   background. The only noise is the wavelengths'
//   (and the pixel footprint's with the box filter).
// - Global: paths continue by sampling the BRDF (cosine-weighted for the diffuse lobe, GGX
//   normals for the specular one, combined by their one-sample mixture pdf), next-event
//   estimation at every vertex, Russian roulette from the fourth vertex; rays that escape see the
//   background as uniform surrounding radiance. Delta lights cannot be hit, so nothing is
//   counted twice.
// - A technique's environment (TechniqueSection::environment: PRT's) replaces the background as
//   the light of rays that escape after a bounce (camera rays still see the background); with
//   direct transport each first hit also samples it once through the BRDF, with a shadow ray.
//   Objects a technique shades itself are Lambertian (SurfaceHit::lambertian), lit by the
//   scene's lights too (a technique's sun is one), as the rasteriser's lighting pass lights them.
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
  // The hero wavelengths: count must be 4. Lights (the scene's emission × the observer's
  // response) by default: the observer's alone drew a narrow lamp's line in few paths or none.
  SamplingSettings wavelengths{4, kLambdaMinNm, kLambdaMaxNm, SamplingStrategy::Lights};
  std::uint32_t seed = 0;    // the image is a deterministic function of the seed and settings
  unsigned threads = 0;      // 0: all hardware threads (the image does not depend on it)
};

// Error naming the setting when out of range.
void validate(const ReferenceSettings& settings);

// The share of a render one process traces (a task of a render split across a cluster,
// batch/): pixel rows [rowBegin, rowEnd) and, of each pixel's samplesPerPixel paths, the path
// indices [sampleBegin, sampleEnd). Path s of a pixel is the same path in every share (its random
// numbers depend on the pixel, s and the seed alone), so shares merge into the image one process
// renders: bit for bit when split by rows.
struct ReferenceRegion {
  int rowBegin = 0, rowEnd = 0;
  int sampleBegin = 0, sampleEnd = 0;

  static ReferenceRegion whole(const ReferenceSettings& s) { return {0, s.height, 0, s.samplesPerPixel}; }
  int rows() const { return rowEnd - rowBegin; }
  int samples() const { return sampleEnd - sampleBegin; }
  bool operator==(const ReferenceRegion&) const = default;
};

// Error naming the range when the region is empty or outside the image or the paths per pixel.
void validate(const ReferenceRegion& region, const ReferenceSettings& settings);

// A region's rows (all of the image's by default), 3 channels each, row 0 at the region's top.
struct ReferenceImage {
  imaging::FloatImage tristimulus;  // mean over the pixel's paths
  // The variance of that mean per channel: sample variance / N, an upper bound for the
  // stratified wavelengths.
  imaging::FloatImage variance;
  // The mean as accumulated (double) minus `tristimulus`, rounded to float: what a merge of
  // sample ranges adds back to weigh each range's mean to about 48 bits (batch/reference_merge.h).
  imaging::FloatImage meanResidual;
};

// Error "SCENE: why" when the scene holds a technique the path tracer does not trace (the
// atmosphere, a nebula): what renderReference says first, and a cluster script before its tasks.
void requireTraceable(const Scene& scene);

// done / total in the region's pixel rows × passes; called from one thread at a time.
using ReferenceProgress = std::function<void(std::size_t done, std::size_t total)>;

// `table` is the Jakob–Hanika table of the scene's colour space.
ReferenceImage renderReference(const Scene& scene, const RgbToSpectrumTable& table,
                               const ReferenceSettings& settings,
                               const ReferenceProgress& progress = {});
// Only `region`'s rows and paths.
ReferenceImage renderReference(const Scene& scene, const RgbToSpectrumTable& table,
                               const ReferenceSettings& settings, const ReferenceRegion& region,
                               const ReferenceProgress& progress = {});

}  // namespace prism::reference
