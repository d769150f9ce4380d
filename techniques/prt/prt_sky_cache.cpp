#include "techniques/prt/prt_sky_cache.h"

#include <cstdio>
#include <fstream>
#include <iterator>
#include <limits>
#include <optional>
#include <string>

#include <fmt/format.h>

#include "core/error.h"
#include "core/atomic_file.h"
#include "core/cache_folder.h"
#include "core/binary_fields.h"
#include "core/data_files.h"
#include "core/fnv1a.h"
#include "spectral/rgb_to_spectrum_cache.h"
#include "techniques/prt/prt_spectra.h"

namespace prism::prt {
namespace {

// Bump when tabulateSky or this format changes what a key's grid holds.
constexpr int kSkyCacheVersion = 1;
constexpr std::string_view kMagic = "prism-prt-sky\n";
constexpr std::size_t kMostEntries = 32;  // 2.6 MB each at 128 × 64: a viewer's sun drags stay bounded

std::string readBytes(const std::filesystem::path& path) {
  if (std::filesystem::is_directory(path)) throw Error(path.string() + ": is a folder, not a file");
  std::ifstream in(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

std::string serialise(const SkyRadianceGrid& grid, std::uint64_t key) {
  std::string bytes(kMagic);
  binary::append(bytes, key);
  binary::append(bytes, grid.width);
  binary::append(bytes, grid.height);
  for (int i = 0; i < 3; ++i) binary::append(bytes, grid.sunDirection[i]);
  for (double e : grid.sunIrradiance) binary::append(bytes, e);
  for (float r : grid.radiance) binary::append(bytes, r);
  binary::append(bytes, fnv1a(bytes));
  return bytes;
}

// Null when the bytes are not a whole grid of this key and size.
std::optional<SkyRadianceGrid> parse(const std::string& bytes, std::uint64_t key, int width, int height) {
  const std::size_t texels = static_cast<std::size_t>(width) * static_cast<std::size_t>(height);
  const std::size_t size = kMagic.size() + sizeof key + 2 * sizeof(int) + (3 + kGridWavelengths) * sizeof(double) +
                           texels * kGridWavelengths * sizeof(float) + sizeof(std::uint64_t);
  if (bytes.size() != size || bytes.compare(0, kMagic.size(), kMagic) != 0) return std::nullopt;
  const std::size_t body = size - sizeof(std::uint64_t);
  if (binary::readAt<std::uint64_t>(bytes, body) != fnv1a(std::string_view(bytes).substr(0, body))) return std::nullopt;
  std::size_t at = kMagic.size();
  auto next = [&]<typename T>(T) {
    const T value = binary::readAt<T>(bytes, at);
    at += sizeof(T);
    return value;
  };
  if (next(std::uint64_t{}) != key || next(int{}) != width || next(int{}) != height) return std::nullopt;
  SkyRadianceGrid grid;
  grid.width = width;
  grid.height = height;
  for (int i = 0; i < 3; ++i) grid.sunDirection[i] = next(double{});
  grid.sunIrradiance.resize(kGridWavelengths);
  for (double& e : grid.sunIrradiance) e = next(double{});
  grid.radiance.resize(texels * kGridWavelengths);
  for (float& r : grid.radiance) r = next(float{});
  return grid;
}

}  // namespace

std::uint64_t skyCacheKey(const PrtSky& sky, int width, int height) {
  const atmosphere::AtmosphereSky& a = sky.atmosphere;
  const atmosphere::AtmosphereParameters& p = a.parameters;
  // As text: a struct's padding bytes are not the values.
  const std::string text = fmt::format(
      "{} {}x{} {} {} {} {} {} {} {} {} {} {} {} {} {} {} {} {} | {} {} {}", kSkyCacheVersion, width, height,
      p.bottomRadiusKm, p.topRadiusKm, p.rayleighScaleHeightKm, p.rayleighScatteringPerKm, p.aerosols,
      p.mieScaleHeightKm, p.mieAngstromAlpha, p.mieAngstromBeta, p.mieSingleScatteringAlbedo, p.miePhaseG,
      p.ozoneColumnDu, p.ozonePeakAltitudeKm, p.ozoneHalfWidthKm, p.groundAlbedo, p.sunAngularRadiusRad,
      p.multipleScattering, a.sunElevationDeg, a.sunAzimuthDeg, a.groundAltitudeM);
  return fnv1a(readBytes(dataFile("atmosphere_spectra.csv")), fnv1a(text));
}

SkyRadianceGrid cachedSky(const PrtSky& sky, int width, int height) {
  const std::uint64_t key = skyCacheKey(sky, width, height);
  const std::filesystem::path path = cacheDirectory() / "prt_sky" / fmt::format("{:016x}.bin", key);
  std::error_code ec;
  requireNoFolderAtEntry(path, "a PRT sky");
  if (std::filesystem::exists(path, ec)) {
    if (std::optional<SkyRadianceGrid> grid = parse(readBytes(path), key, width, height)) {
      touchCacheEntry(path);
      return *grid;
    }
    std::fprintf(stderr, "prism: cache entry %s is damaged (not a sky grid of this key): tabulating it again\n",
                 path.string().c_str());
  }
  std::filesystem::create_directories(path.parent_path(), ec);
  requireWritable(path);  // before the work, not after
  SkyRadianceGrid grid = tabulateSky(sky, width, height);
  writeFileAtomically(path, serialise(grid, key));
  pruneCacheFolder(path.parent_path(), "", ".bin", kMostEntries, std::numeric_limits<std::uintmax_t>::max());
  return grid;
}

}  // namespace prism::prt
