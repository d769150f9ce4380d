#include "spectral/rgb_to_spectrum_cache.h"

#include <zlib.h>

#include <cstdio>
#include <cstdlib>
#include <map>
#include <mutex>

#include "shared_cpp.h"
#include "spectral/colour_space.h"
#include "core/error.h"
#include "spectral/observer.h"
#include "spectral/rgb_to_spectrum_optimiser.h"
#include "spectral/sigmoid_fit.h"

namespace prism::shared {
#include "sigmoid.glsl"
}

namespace prism {
namespace {

// Bump when the optimiser or the table's meaning changes.
constexpr int kOptimiserVersion = 1;

std::uint32_t inputHash(const std::string& gamutName, int resolution) {
  const RgbColourSpace& gamut = colourSpace(gamutName);
  std::vector<double> key{static_cast<double>(kOptimiserVersion), static_cast<double>(resolution),
                          gamut.red.x,   gamut.red.y,   gamut.green.x, gamut.green.y,
                          gamut.blue.x,  gamut.blue.y,  gamut.white.x, gamut.white.y,
                          shared::kReflectanceMinNm, shared::kReflectanceMaxNm};
  for (const Spectrum& curve : observer("cie1931").curves)
    key.insert(key.end(), curve.values().begin(), curve.values().end());
  Spectrum light = gamutWhiteIlluminant(gamut);
  key.insert(key.end(), light.values().begin(), light.values().end());
  uLong crc = crc32(0L, reinterpret_cast<const Bytef*>(gamutName.data()), static_cast<uInt>(gamutName.size()));
  crc = crc32(crc, reinterpret_cast<const Bytef*>(key.data()), static_cast<uInt>(key.size() * sizeof(double)));
  return static_cast<std::uint32_t>(crc);
}

}  // namespace

std::filesystem::path cacheDirectory() {
  if (const char* dir = std::getenv("PRISM_CACHE_DIR"); dir && *dir) return dir;
  if (const char* xdg = std::getenv("XDG_CACHE_HOME"); xdg && *xdg) return std::filesystem::path(xdg) / "prism";
  if (const char* home = std::getenv("HOME"); home && *home)
    return std::filesystem::path(home) / ".cache" / "prism";
  throw Error("no cache folder: set PRISM_CACHE_DIR (or HOME)");
}

std::filesystem::path rgbToSpectrumCachePath(const std::string& gamut, int resolution) {
  char name[96];
  std::snprintf(name, sizeof name, "rgb2spec-%s-%d-%08x.prismlut", gamut.c_str(), resolution,
                static_cast<unsigned>(inputHash(gamut, resolution)));
  return cacheDirectory() / name;
}

RgbToSpectrumTable cachedRgbToSpectrumTable(
    const std::string& gamut, int resolution,
    const std::function<void(std::size_t, std::size_t)>& progress) {
  std::filesystem::path path = rgbToSpectrumCachePath(gamut, resolution);
  if (std::filesystem::exists(path)) {
    try {
      RgbToSpectrumTable table = RgbToSpectrumTable::load(path);
      if (table.gamut() == gamut && table.resolution() == resolution) return table;
    } catch (const Error&) {
      // A damaged cache entry is rebuilt below, never trusted.
    }
  }
  RgbToSpectrumTable table = buildRgbToSpectrumTable({gamut, resolution, 0, progress});
  table.save(path);
  return table;
}

const RgbToSpectrumTable& rendererRgbToSpectrumTable(
    const std::string& gamut, const std::function<void(std::size_t, std::size_t)>& progress) {
  static std::mutex mutex;
  static std::map<std::string, RgbToSpectrumTable, std::less<>> tables;  // nodes never move
  std::lock_guard lock(mutex);
  auto it = tables.find(gamut);
  if (it == tables.end())
    it = tables.emplace(gamut, cachedRgbToSpectrumTable(gamut, kRendererTableResolution, progress)).first;
  return it->second;
}

}  // namespace prism
