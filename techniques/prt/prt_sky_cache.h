// The spectral sky's grid (prt_sky.h), cached on disk: tabulating it takes ~0.6 s on 2 cores in
// Release (tens of seconds under the sanitizers), and every process that loads a scene under the
// spectral sky — a render, the viewer, each test — would tabulate it again. Cached in
// cacheDirectory()/prt_sky/KEY.bin, KEY the FNV-1a hash of everything that shapes the grid: the
// format's version, the atmosphere's parameters, the sun's position, the ground's altitude, the
// grid's size and the bytes of data/atmosphere_spectra.csv (the solar spectrum and ozone). Written
// atomically after requireWritable; an entry that is not this key's grid, or whose checksum fails,
// is said so in one line on stderr and tabulated again. The 32 newest entries are kept (2.6 MB
// each): dragging the sun in the viewer writes one a position.
#pragma once

#include <cstdint>

#include "techniques/prt/prt_sky.h"

namespace prism::prt {

// tabulateSky(sky, width, height), from the cache when there.
SkyRadianceGrid cachedSky(const PrtSky& sky, int width = kSkyGridWidth, int height = kSkyGridHeight);
std::uint64_t skyCacheKey(const PrtSky& sky, int width, int height);

}  // namespace prism::prt
