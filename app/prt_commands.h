// `prism prt …`: spectral precomputed radiance transfer (techniques/prt). Each command writes its
// result to stdout and throws prism::Error on bad input; files are written atomically.
#pragma once

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "techniques/prt/transfer_bake.h"

namespace prism::app {

struct PrtBakeOptions {
  std::string input;           // a scene (.json) or a glTF model (.gltf, .glb)
  std::optional<int> samples;  // directions per vertex; unset: the scene's prt.samples, else 1024
  bool shadows = true;         // false: unshadowed (so is a scene whose prt.shadows is false)
  std::string cacheDir;    // default: Prism's cache folder
  std::string part;        // "I/N": only task I of N's vertices, written to `output` (transfer_part.h)
  std::string output;      // the part's file (with --part only)
  unsigned threads = 0;    // 0: every core
};
// Bakes (or reads from the cache) the SH-5 transfer of every vertex of the input's meshes, all
// meshes occluding each other; prints what it did and the rays per second. With `part`, bakes
// that task's share of the vertices into a part for `prism merge` (skipped when the file already
// holds it, whole).
void runPrtBake(const PrtBakeOptions& options);
// What runPrtBake bakes: the input's mesh (z-up, world space) and the cache file its transfer
// goes to (`cacheDir`, else Prism's cache; transfer_bake.h's transferCacheFile).
struct PrtBakeTarget {
  prt::BakeSettings settings;  // the options resolved against the scene's section
  prt::PrtMesh mesh;
  std::uint64_t key = 0;
  std::filesystem::path cacheFile;
};
PrtBakeTarget prtBakeTarget(const PrtBakeOptions& options);

struct PrtReportOptions {
  std::string input;                // a scene or glTF model; empty: the ColorChecker height field
  // One environment: a scene's own (`input` with a prt section or the spectral sky, none of the
  // below given), a map, or `environment` (default sky) under `illuminant` (default F4) or, for
  // atmosphere, the scene's spectral sky if it has one, else Prism's, with its sun (default the
  // scene's, else 30° up, azimuth 180°). Options of another environment than the one used are refused.
  std::optional<std::string> illuminant;
  std::optional<std::string> environment;  // sky | uniform | atmosphere (Prism's spectral sky, its sun below)
  std::optional<double> sunElevationDeg;
  std::optional<double> sunAzimuthDeg;
  std::string exr;                  // or an equirectangular linear-sRGB EXR (row 0 at the zenith)
  std::vector<double> rotate;       // X, Y, Z, degrees: the environment turned (empty: not)
  std::optional<int> patchVertices;  // along each side of a ColorChecker patch (no input; default 16)
  std::optional<int> samples;       // unset: a scene's prt.samples, else 1024
  std::string plotFile;             // optional: the sweep as an SVG
  std::string coloursFile;          // optional: per-vertex display colours as a PLY
  // Of spectral PRT with this many functions, 0: the 5 nm reference; unset: 8, or as many as the
  // scene's spectra give when fewer.
  std::optional<int> coloursM;
  bool json = false;
};
// The ColorChecker object (or a scene's meshes) under a spectral environment: spectral PRT for m = 1..16 and RGB-PRT
// against the 5 nm reference, mean and max ΔE94 and ΔE00 over the vertices.
void runPrtReport(const PrtReportOptions& options);

struct PrtMetamersOptions {
  std::string reflectance = "light skin";  // a ColorChecker patch name or a spectral CSV
  std::string match = "D65";
  std::string target = "A";
  std::vector<std::string> under{"D65", "A", "F2"};
  int patchVertices = 16;
  int samples = 1024;
  bool json = false;
};
// The paper's metamer scene: the reflectance and its metamer (same colour under `match`, most
// different under `target`) on the ColorChecker height field, rendered by spectral PRT (m ≤ 8)
// under each illuminant's overcast sky; prints the two halves' mean and max ΔE00 per illuminant.
void runPrtMetamers(const PrtMetamersOptions& options);

}  // namespace prism::app
