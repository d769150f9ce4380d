#include "techniques/nebula/nebula_density.h"

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstring>
#include <fstream>
#include <limits>
#include <sstream>
#include <string>
#include <utility>

#include <fmt/format.h>

#include "core/atomic_file.h"
#include "core/error.h"
#include "core/json_schema.h"
#include "core/input_file.h"
#include "core/parallel_for.h"
#include "techniques/nebula/nebula_integrals.h"

namespace prism::nebula {

static_assert(std::endian::native == std::endian::little, "density files are little-endian float32");

TrilinearAxis trilinearAxis(double u, int n) {
  TrilinearAxis axis;
  shared::f64::nebulaTrilinearAxis(u, n, axis.i0, axis.i1, axis.f);
  return axis;
}

std::string coarseGridWarning(const DensityGrid& grid) {
  if (std::min({grid.nx, grid.ny, grid.nz}) >= kFineGridVoxels) return "";
  return fmt::format("the density grid is {}×{}×{}: each star's optical depth is kept per voxel of it, so a grid of "
                     "fewer than {} voxels an axis gives an image of its own (a uniform cloud 5 % darker at 8³, 30 % "
                     "at 2³ than at 64³); a finer grid of the same density fixes it",
                     grid.nx, grid.ny, grid.nz, kFineGridVoxels);
}

std::string emptyGridWarning(const DensityGrid& grid) {
  const float largest = grid.values.empty() ? 0.0f : *std::max_element(grid.values.begin(), grid.values.end());
  if (largest >= std::numeric_limits<float>::min()) return "";
  if (largest > 0.0f)
    return fmt::format("the density is below float's smallest normal number ({:.3g}) in every voxel, the largest {:.3g}, "
                       "so the nebula neither glows nor dims what lies behind it: a file written big-endian? Density "
                       "files hold little-endian float32",
                       std::numeric_limits<float>::min(), largest);
  return "the density is 0 in every voxel, so the nebula neither glows nor dims what lies behind it (noise: a bias "
         "below about −amplitude empties the cube)";
}

double DensityGrid::sample(const glm::dvec3& p) const {
  if (p.x < 0.0 || p.y < 0.0 || p.z < 0.0 || p.x > 1.0 || p.y > 1.0 || p.z > 1.0) return 0.0;
  const TrilinearAxis ax = trilinearAxis(p.x, nx), ay = trilinearAxis(p.y, ny), az = trilinearAxis(p.z, nz);
  const int x0 = ax.i0, x1 = ax.i1, y0 = ay.i0, y1 = ay.i1, z0 = az.i0, z1 = az.i1;
  const double fx = ax.f, fy = ay.f, fz = az.f;
  auto lerp = [](double a, double b, double t) { return a + (b - a) * t; };
  double c00 = lerp(at(x0, y0, z0), at(x1, y0, z0), fx), c10 = lerp(at(x0, y1, z0), at(x1, y1, z0), fx);
  double c01 = lerp(at(x0, y0, z1), at(x1, y0, z1), fx), c11 = lerp(at(x0, y1, z1), at(x1, y1, z1), fx);
  return lerp(lerp(c00, c10, fy), lerp(c01, c11, fy), fz);
}

namespace {

std::uint64_t splitmix64(std::uint64_t& state) {
  std::uint64_t z = (state += 0x9e3779b97f4a7c15ULL);
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
  return z ^ (z >> 31);
}

std::array<int, 512> permutation(std::uint64_t seed) {
  std::array<int, 512> p{};
  for (int i = 0; i < 256; ++i) p[static_cast<std::size_t>(i)] = i;
  std::uint64_t state = seed;
  for (int i = 255; i > 0; --i) {  // Fisher–Yates, our own so the result is the same everywhere
    int j = static_cast<int>(splitmix64(state) % static_cast<std::uint64_t>(i + 1));
    std::swap(p[static_cast<std::size_t>(i)], p[static_cast<std::size_t>(j)]);
  }
  for (std::size_t i = 0; i < 256; ++i) p[i + 256] = p[i];
  return p;
}

double fade(double t) { return t * t * t * (t * (t * 6 - 15) + 10); }
double grad(int hash, double x, double y, double z) {
  int h = hash & 15;
  double u = h < 8 ? x : y, v = h < 4 ? y : (h == 12 || h == 14 ? x : z);
  return ((h & 1) ? -u : u) + ((h & 2) ? -v : v);
}

double noise(const std::array<int, 512>& p, glm::dvec3 q) {
  glm::dvec3 f = glm::floor(q);
  int X = static_cast<int>(f.x) & 255, Y = static_cast<int>(f.y) & 255, Z = static_cast<int>(f.z) & 255;
  q -= f;
  double u = fade(q.x), v = fade(q.y), w = fade(q.z);
  auto P = [&p](int i) { return p[static_cast<std::size_t>(i)]; };
  int A = P(X) + Y, AA = P(A) + Z, AB = P(A + 1) + Z, B = P(X + 1) + Y, BA = P(B) + Z, BB = P(B + 1) + Z;
  auto lerp = [](double t, double a, double b) { return a + t * (b - a); };
  return lerp(w,
              lerp(v, lerp(u, grad(P(AA), q.x, q.y, q.z), grad(P(BA), q.x - 1, q.y, q.z)),
                   lerp(u, grad(P(AB), q.x, q.y - 1, q.z), grad(P(BB), q.x - 1, q.y - 1, q.z))),
              lerp(v, lerp(u, grad(P(AA + 1), q.x, q.y, q.z - 1), grad(P(BA + 1), q.x - 1, q.y, q.z - 1)),
                   lerp(u, grad(P(AB + 1), q.x, q.y - 1, q.z - 1), grad(P(BB + 1), q.x - 1, q.y - 1, q.z - 1))));
}

}  // namespace

double perlinNoise(const glm::dvec3& p, std::uint64_t seed) { return noise(permutation(seed), p); }

DensityGrid generateFbm(const NoiseParameters& params, unsigned threads,
                        const std::function<void(std::size_t done, std::size_t total)>& progress) {
  if (params.resolution < 2 || params.resolution > 1024 || params.octaves < 1 || params.octaves > 16)
    throw Error(fmt::format("density noise: resolution must be 2…1024 and octaves 1…16 (got {} and {})",
                            params.resolution, params.octaves));
  auto perm = permutation(params.seed);
  int n = params.resolution;
  DensityGrid grid{n, n, n, std::vector<float>(static_cast<std::size_t>(n) * n * n)};
  parallelFor(static_cast<std::size_t>(n), threads, [&](std::size_t k) {
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i) {
        glm::dvec3 p((i + 0.5) / n, (j + 0.5) / n, (static_cast<double>(k) + 0.5) / n);
        double sum = 0.0, amp = 1.0, freq = params.frequency;
        for (int o = 0; o < params.octaves; ++o, amp *= params.gain, freq *= 2.0)
          sum += amp * noise(perm, p * freq + glm::dvec3(o * 17.31));
        double r = glm::length(p - glm::dvec3(0.5));
        double t = std::clamp((0.5 - r) / 0.25, 0.0, 1.0);
        double falloff = t * t * (3.0 - 2.0 * t);
        double d = std::max(0.0, (params.amplitude * sum + params.bias) * falloff);
        grid.values[(k * static_cast<std::size_t>(n) + static_cast<std::size_t>(j)) * static_cast<std::size_t>(n) +
                    static_cast<std::size_t>(i)] = static_cast<float>(d);
      }
  }, progress);
  return grid;
}

DeferredDensity::DeferredDensity(DensityGrid grid) : mGrid(std::move(grid)) {}

DeferredDensity::DeferredDensity(const NoiseParameters& noise) : mNoise(noise) {}

glm::ivec3 DeferredDensity::size() const {
  if (mNoise) return glm::ivec3(mNoise->resolution);
  return {mGrid.nx, mGrid.ny, mGrid.nz};
}

const DensityGrid& DeferredDensity::grid(const std::function<void(std::size_t done, std::size_t total)>& progress) const {
  if (mNoise) std::call_once(mMade, [&] { mGrid = generateFbm(*mNoise, 0, progress); });
  return mGrid;
}

DensityGrid readDensityFile(const std::filesystem::path& path) {
  requireInputFile(path, "a density file");
  std::ifstream in(path, std::ios::binary);
  std::string file = path.string();
  if (!in) throw Error(FileLocation{file}, "cannot open the density file");
  // The header first (two short lines), so that a file too long for its sizes is refused
  // before it is read whole.
  std::string bytes(64, '\0');
  in.read(bytes.data(), static_cast<std::streamsize>(bytes.size()));
  bytes.resize(static_cast<std::size_t>(in.gcount()));
  std::size_t eol1 = bytes.find('\n');
  if (eol1 == std::string::npos || bytes.compare(0, eol1, "prism-density 1") != 0)
    throw Error(FileLocation{file, 1}, "not a Prism density file (expected the line 'prism-density 1')");
  std::size_t eol2 = bytes.find('\n', eol1 + 1);
  if (eol2 == std::string::npos) throw Error(FileLocation{file, 2}, "missing the size line 'NX NY NZ'");
  std::istringstream sizes(bytes.substr(eol1 + 1, eol2 - eol1 - 1));
  long long nx = 0, ny = 0, nz = 0;
  std::string extra;
  if (!(sizes >> nx >> ny >> nz) || (sizes >> extra) || nx < 1 || ny < 1 || nz < 1 || nx > 1024 || ny > 1024 ||
      nz > 1024)
    throw Error(FileLocation{file, 2}, "the size line must be three integers 1…1024, 'NX NY NZ'");
  std::size_t count = static_cast<std::size_t>(nx * ny * nz), offset = eol2 + 1;
  std::size_t expected = count * sizeof(float);
  std::error_code ec;
  auto fileSize = static_cast<std::size_t>(std::filesystem::file_size(path, ec));
  if (ec) throw Error(FileLocation{file}, "cannot read the density file's size");
  std::size_t found = fileSize - offset;
  if (found != expected)
    throw Error(FileLocation{file}, fmt::format("byte {}: expected {} bytes of float32 data ({}×{}×{}), found {}",
                                                offset, expected, nx, ny, nz, found));
  DensityGrid grid{static_cast<int>(nx), static_cast<int>(ny), static_cast<int>(nz), std::vector<float>(count)};
  in.clear();
  in.seekg(static_cast<std::streamoff>(offset));
  in.read(reinterpret_cast<char*>(grid.values.data()), static_cast<std::streamsize>(expected));
  if (in.gcount() != static_cast<std::streamsize>(expected)) throw Error(FileLocation{file}, "the density file changed while read");
  // Within a scene's limit on numbers: 3.4e38 overflowed the march and blamed the output image.
  for (std::size_t v = 0; v < count; ++v)
    if (!(grid.values[v] >= 0.0f && grid.values[v] <= schema::kFloatInputLimit))
      throw Error(FileLocation{file},
                  fmt::format("byte {}: voxel ({}, {}, {}) is {}: densities must lie within 0–{:g}",
                              offset + v * sizeof(float), v % static_cast<std::size_t>(nx),
                              v / static_cast<std::size_t>(nx) % static_cast<std::size_t>(ny),
                              v / static_cast<std::size_t>(nx * ny), grid.values[v], schema::kFloatInputLimit));
  return grid;
}

void writeDensityFile(const std::filesystem::path& path, const DensityGrid& grid) {
  std::string bytes = fmt::format("prism-density 1\n{} {} {}\n", grid.nx, grid.ny, grid.nz);
  std::size_t at = bytes.size();
  bytes.resize(at + grid.values.size() * sizeof(float));
  std::memcpy(bytes.data() + at, grid.values.data(), grid.values.size() * sizeof(float));
  writeFileAtomically(path, bytes);
}

}  // namespace prism::nebula
