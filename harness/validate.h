// `prism validate`: Pérez García's experiments, reproduced against Prism's own ground truth.
// The thesis's 15 spheres under D65, under its LED lamp, under a narrow blue LED and under F11
// (its D65 scene with the lamp changed), rendered by
// the rasteriser in RGB, naive (box) and Jakob–Hanika modes with 200 wavelengths, and in
// Jakob–Hanika mode with 16 wavelengths a frame (the real-time setting: the uniform grid or the
// lights' pdf rotated each frame and 32 frames accumulated, as a still camera gets it, and one
// frame alone by the uniform grid, the observer's importance and the lights' pdf, the latter two
// averaged over 8 frames in a row since their wavelengths move from frame to frame), each
// compared in CIEDE2000 and MAE with the reference path tracer (direct lighting, pixel centres:
// what the rasteriser computes, exactly).
// Writes DIR/index.html (images side by side, heat maps, histograms, the table) and
// DIR/results.json, prints the table, and fails (exit 1) when a bound below is broken:
//   spheres under D65, Jakob–Hanika, 16 wavelengths a frame, accumulated: mean ΔE00 ≤ 0.5
//   spheres under the blue LED, the same: mean ΔE00 ≤ 1.0
// And spectral PRT's Macbeth and metamer scenes, under their environments, in its three modes
// (spectral m = 8, RGB-PRT, the 5 nm reference) against the path tracer under the same
// environment before projection (the SH-5 band limit and the noise common to all three):
//   spectral PRT: mean ΔE00 at most 0.05 above the 5 nm reference's (what its basis adds)
// And the example nebulae, in the Hubble palette and in natural colour, by the GPU marcher's
// projection, light–density, analytic and pre-integration against the CPU's reference
// (validate_nebula.h):
//   projection, analytic and pre-integration: ΔE00 ≤ 1 at every pixel (mean ≤ 0.5)
//   light–density: mean ΔE00 ≤ 0.5
// Split across tasks (a Slurm array, validate_parts.h): `--task I/N` runs task I's share of the
// sixteen experiments (four sphere scenes, five reef depths, three PRT scenes, four nebulae) and
// writes its part
// (validateExperimentCount(only) of them at most); `--collect`
// writes DIR/results.json and DIR/index.html from the parts, the same files a whole run writes.
// `--only NAME,…` runs those experiments alone (results.json's "scene" names), split and
// collected the same way, and checks the bounds of what it ran.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace prism::harness {

struct ValidateOptions {
  std::filesystem::path output = "out/validate";
  std::filesystem::path scenes;  // default: the example scenes
  bool quick = false;            // 240×135, 64 paths per pixel (CI); else 640×360, 256
  bool json = false;             // print results.json instead of the table
  std::string task;              // "I/N": only task I of N's experiments, into DIR/parts (skipped when there)
  bool collect = false;          // the report from DIR/parts instead of running experiments
  std::optional<int> tasks;      // with collect: only the parts of a split into this many tasks
  std::vector<std::string> only;  // experiment names, in any order; empty: every one
  unsigned threads = 0;           // the CPU's share of every experiment (0: all hardware threads)
};
// 0 when every bound holds, 1 otherwise (the report is written either way); a task: 0.
int runValidate(const ValidateOptions& options);

// How many experiments a sweep of `only` runs (every one when empty): the most tasks it splits
// into. Error "--only: no experiment "NAME" (…)" for a name that is none.
int validateExperimentCount(const std::vector<std::string>& only);

}  // namespace prism::harness
