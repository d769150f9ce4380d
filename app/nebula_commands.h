// `prism nebula`: spectral nebulae after Barrès 2023 (techniques/nebula/) —
// `basis` prints (and plots) the greedy exp(−a/λ) basis and its error after each element; `sweep`
// measures a render's error against the basis size; `render` marches a
// nebula scene with one of the five methods to an EXR (linear channels) or a PNG, on the CPU or
// (projection, light-density) with `--gpu` on the GPU; `density` writes a scene's density grid as
// a prism-density file; `bench` times the GPU marcher against the CPU's for 1, 6 and 32 stars.
#pragma once

#include <filesystem>
#include <optional>
#include <string>

namespace prism::app {

struct NebulaBasisOptions {
  double lambda0Um = 0.38, lambda1Um = 0.78;
  double maxDepthUm = 1.0;  // the family: e^(−g/λ), g ∈ [0, this]
  double maxExponentUm = 2.0;
  double spacingUm = 0.0;   // minimum spacing of the exponents (0: the free greedy)
  int count = 6;
  bool json = false;
  std::filesystem::path plotFile;  // SVG of the error after each element (log_plot.h)
};
void runNebulaBasis(const NebulaBasisOptions& options);

// The projection method's error against the basis size: a nebula scene rendered on the CPU with
// 1 to `maxBasis` elements, each against the reference (double integration), max relative error
// per pixel over pixels ≥ 1 % of their channel's peak; printed, and plotted with the 2 % bound.
struct NebulaSweepOptions {
  std::filesystem::path scene;
  std::string filters;           // empty: the scene's
  std::optional<int> steps;      // unset: the scene's
  int maxBasis = 5;
  std::optional<double> basisDepthUm;  // the basis's family g ≤ this; unset: RenderSettings' default
  std::optional<int> size;       // the camera's longer side, in pixels (the aspect kept); unset: the scene's
  bool noLines = false;
  bool json = false;
  std::filesystem::path plotFile;
  unsigned threads = 0;
};
void runNebulaSweep(const NebulaSweepOptions& options);

struct NebulaRenderOptions {
  std::filesystem::path scene;
  std::filesystem::path output;  // .exr or .png
  std::string method = "projection";
  std::string filters;           // empty: the scene's ("hubble" or "cie1931")
  std::optional<int> steps;      // unset: the scene's
  std::optional<int> size;       // the camera's longer side in pixels; unset: the scene's
  // Each method's own options, unset: RenderSettings' defaults; given to a method that has no use
  // for it, refused.
  std::optional<int> basisSize;           // projection, light-density
  std::optional<double> basisDepthUm;     // projection, light-density: the basis's family g ≤ this
  std::optional<int> lightBasisSize;      // light-density
  std::optional<int> referenceIntervals;  // the reference by Simpson (itself, or --compare's)
  int uniformSamples = 0;
  bool compare = false;          // also render the reference and print the error against it
  bool noLines = false;
  bool gpu = false;              // march on the GPU (headless EGL context)
  unsigned threads = 0;
};
void runNebulaRender(const NebulaRenderOptions& options);

void runNebulaDensity(const std::filesystem::path& scene, const std::filesystem::path& output);

// On benchNebulaModel (32³, 100 steps, Hubble, no lines) at size × size pixels (64 by default),
// for 1, 6 and 32 stars: the CPU's double integration (21 λ a step, one thread) and projection
// (one thread), unless `cpu` is false (a GPU's run at a large size, where the CPU's would take
// minutes), and the GPU's reference, projection and light–density marches (march + finish, GPU
// time by timestamps) and a filter edit (wall: the CPU's refiltering and the finish), the median of
// `repeats`.
struct NebulaBenchOptions {
  int repeats = 5;
  int size = 64;
  bool cpu = true;
};
void runNebulaBench(const NebulaBenchOptions& options);

}  // namespace prism::app
