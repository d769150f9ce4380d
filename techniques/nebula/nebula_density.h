// The nebula's density: a grid of non-negative values over the unit cube [0,1]³ (the volume's
// box), from fractional Brownian motion over Perlin noise or from a file of Prism's own format.
//
// File format ("prism-density", version 1): an ASCII header of two lines, then raw data:
//   prism-density 1\n
//   NX NY NZ\n                      each 1…1024
//   NX·NY·NZ little-endian float32 densities, x fastest, then y, then z (voxel centres at
//   ((i+½)/NX, (j+½)/NY, (k+½)/NZ) of the box), each finite and ≥ 0; nothing after them.
// A bad file is refused in one line naming the file and the place (line, or byte offset).
#pragma once

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

#include <glm/glm.hpp>

namespace prism::nebula {

// One axis of a trilinear lookup between voxel centres, clamped at the faces: the voxels i0 and i1
// around u ∈ [0, 1] on an axis of n voxels, and i1's weight f. What every grid over the unit cube
// (the density, the per-voxel fields of the renderer) samples with.
struct TrilinearAxis {
  int i0 = 0, i1 = 0;
  double f = 0.0;
};
TrilinearAxis trilinearAxis(double u, int n);

struct DensityGrid {
  int nx = 0, ny = 0, nz = 0;
  std::vector<float> values;  // x fastest

  float at(int i, int j, int k) const {
    return values[static_cast<std::size_t>((k * ny + j) * nx + i)];
  }
  // Trilinear between voxel centres, clamped at the faces; 0 outside the unit cube.
  double sample(const glm::dvec3& p) const;
};

// One line for stderr when the grid has fewer than kFineGridVoxels voxels along an axis ("" else):
// each star's optical depth is kept per voxel of the density grid (nebula_precomputed.h), so a
// coarse grid makes an image of its own. A new-user review's uniform cloud, three stars, Hubble
// palette, reference, the image's B: 64³ 0.1066, 32³ 0.1062, 8³ 0.1005, 4³ 0.0916, 2³ 0.0725,
// 1³ 0.175 (its brightest pixel 6× the converged one).
inline constexpr int kFineGridVoxels = 16;
std::string coarseGridWarning(const DensityGrid& grid);
// Empty, or that the grid holds no density anywhere (noise whose bias is below about −amplitude, a
// file of zeros) or none above float's subnormals (1.0 written big-endian reads 4.6e-41): a valid
// nebula that renders nothing, which a user would not expect unannounced.
std::string emptyGridWarning(const DensityGrid& grid);

// fBm over Perlin's improved noise (Perlin 2002): Σ_{o<octaves} gainᵒ·noise(frequency·2ᵒ·p),
// scaled by `amplitude`, plus `bias`, shaped by a radial falloff so that the cloud fades before
// the box's faces (1 inside radius 0.25 of the centre, 0 beyond 0.5, smoothstep between), and
// clamped at 0. Deterministic: the permutation comes from `seed` through splitmix64.
struct NoiseParameters {
  int resolution = 128;
  int octaves = 5;
  double frequency = 3.0;
  double amplitude = 1.6;
  double gain = 0.5;
  double bias = 0.35;
  std::uint64_t seed = 1;
};
// progress, if set, is called after each z slice with (slices done, slices in all).
DensityGrid generateFbm(const NoiseParameters& p, unsigned threads = 0,
                        const std::function<void(std::size_t done, std::size_t total)>& progress = {});

// A density given now (a file's) or generated from noise at its first use, then kept: a scene
// holds its nebula's noise unmade until the precomputation, which shows its progress (512³ takes
// about 15 s on two cores), and copies of the scene share what was made.
class DeferredDensity {
 public:
  explicit DeferredDensity(DensityGrid grid);
  explicit DeferredDensity(const NoiseParameters& noise);
  // NX, NY, NZ, without generating.
  glm::ivec3 size() const;
  // The noise it is made of; empty for a given grid.
  const std::optional<NoiseParameters>& noise() const { return mNoise; }
  // Generates it on the first call (with all threads, reporting to `progress`); thread-safe.
  const DensityGrid& grid(const std::function<void(std::size_t done, std::size_t total)>& progress = {}) const;

 private:
  std::optional<NoiseParameters> mNoise;
  mutable std::once_flag mMade;
  mutable DensityGrid mGrid;
};

// Perlin's improved noise at p, for the permutation of a seed, in about [−1, 1].
double perlinNoise(const glm::dvec3& p, std::uint64_t seed);

DensityGrid readDensityFile(const std::filesystem::path& path);
void writeDensityFile(const std::filesystem::path& path, const DensityGrid& grid);  // atomically

}  // namespace prism::nebula
