#include "spectral/rgb_to_spectrum_cache.h"

#include <zlib.h>

#include <cstdio>
#include <cstdlib>
#include <map>
#include <mutex>
#include <utility>

#include "shared_cpp.h"
#include "spectral/colour_space.h"
#include "core/atomic_file.h"
#include "core/cache_folder.h"
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
constexpr int kOptimiserVersion = 2;

// How much worse than a fresh fit a stored node may reproduce its colour (CIE76) and be trusted:
// the builder seeds each fit from its neighbour, which lands within hundredths of a fresh fit.
constexpr double kTrustedNodeDeltaE = 0.5;

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

template <class... Args>
std::string formatted(const char* format, Args... args) {
  char buffer[160];
  std::snprintf(buffer, sizeof buffer, format, args...);
  return buffer;
}

// Why a loaded table cannot be trusted, or empty when it can: a checksum only proves the bytes
// are the ones written. A few nodes spread over the three blocks and the brightness range must
// reproduce their colours about as well as a fresh fit does (a forged or stale table that is
// consistent with its checksum reproduces nothing).
std::string untrustworthy(const RgbToSpectrumTable& table) {
  const RgbColourSpace& gamut = colourSpace(table.gamut());
  const SigmoidFitter fitter(gamut, gamutWhiteIlluminant(gamut), cie1931Observer());
  const int n = table.resolution(), mid = n / 2;
  for (int block = 0; block < 3; ++block) {
    for (int zi : {n - 1, mid, n / 4}) {
      for (auto [yi, xi] : {std::pair{0, 0}, std::pair{mid, mid}, std::pair{n - 1, 0}}) {
        glm::vec3 rgb = table.nodeRgb(block, zi, yi, xi);
        Eigen::Vector3d target(rgb.x, rgb.y, rgb.z);
        double stored = fitter.deltaE76(target, table.coefficients(block, zi, yi, xi));
        double fresh = fitter.fit(target).deltaE76;
        if (!(stored <= fresh + kTrustedNodeDeltaE))
          return formatted("node (%d, %d, %d, %d) is ΔE76 %.3g from its colour, a fresh fit %.3g", block, zi, yi,
                           xi, stored, fresh);
      }
    }
  }
  return {};
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
  requireNoFolderAtEntry(path, "the upsampling table");
  if (std::filesystem::exists(path)) {
    // A damaged entry is said so, in one line, and rebuilt below; never trusted.
    std::string damage;
    try {
      RgbToSpectrumTable table = RgbToSpectrumTable::load(path);
      if (table.gamut() != gamut || table.resolution() != resolution)
        damage = formatted("holds %s at %d³", table.gamut().c_str(), table.resolution());
      else if (table.inputsHash() != inputHash(gamut, resolution))
        damage = formatted("made from other inputs: hash %08x, this build's %08x", table.inputsHash(),
                           inputHash(gamut, resolution));
      else
        damage = untrustworthy(table);
      if (damage.empty()) return table;
    } catch (const Error& e) {
      damage = e.what();
    }
    std::fprintf(stderr, "prism: cache entry %s is damaged (%s): rebuilding\n", path.string().c_str(),
                 excerpt(damage, 160).c_str());
  }
  requireWritable(path);  // before a minute of work, not after
  RgbToSpectrumTable table = buildRgbToSpectrumTable({gamut, resolution, 0, progress});
  table.setInputsHash(inputHash(gamut, resolution));
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
