// `prism bench SCENE.json`: GPU time per pass from timer queries, RGB mode beside spectral modes
// at several wavelength counts; the linear fit t(n) = a·n + b of frame time against the
// wavelength count, spectral/RGB ratios, the GPU memory the renderer holds in each mode, and a
// plot of frame time against n. Each timed frame restarts as if camera and lights had moved (the
// G-buffer and every shadow map drawn), but for two configurations at 16 wavelengths: a still
// camera's frame, which accumulates and draws from the lighting pass on, and a camera orbiting
// under still lights, whose frames draw the shadow maps whose view it moves.
//
// The configurations are measured round by round (RGB, 4, 8, … λ, the G-buffer, water and sky
// variants, then again), not each in one block: on a shared machine the load drifts during a run
// and moved spheres_d65's 16 λ / RGB ratio between 1.13 and 1.34 from run to run. Each ratio is
// taken within a round, where both sides saw the same load, and reported as the median of the
// rounds with its spread (the lowest and highest round).
#pragma once

#include <filesystem>
#include <optional>
#include <vector>

#include "render/frame_settings.h"

namespace prism::harness {

inline constexpr int kDefaultBenchRounds = 5;
// The most --frames and --warmup take.
inline constexpr int kMaxBenchFrames = 1000000;

struct SceneBenchOptions {
  std::filesystem::path scene;
  std::vector<int> wavelengths{4, 8, 16, 32, 64, 128, 256};
  render::FrameSettings settings;  // width, height, lookup, … in RGB mode (the mode is set per configuration)
  int frames = 100;                // timed frames per configuration, spread evenly over the rounds
  std::optional<int> rounds;       // at most `frames`; unset: kDefaultBenchRounds, or `frames` when fewer
  int warmup = 3;                  // untimed frames before each configuration in every round
  bool json = false;
  std::filesystem::path plot;      // .svg, optional
};
void runSceneBench(const SceneBenchOptions& options);

}  // namespace prism::harness
