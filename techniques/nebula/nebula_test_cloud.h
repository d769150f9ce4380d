// The nebula tests' small cloud, shared by the CPU tests and the GPU marcher's: a 24³ fBm density
// of dust that absorbs and scatters, up to five stars (the fourth outside the cube) and a 32×32
// image — small enough to march in seconds on the CPU or on llvmpipe. Emission is each test's.
#pragma once

#include <string>
#include <utility>

#include "techniques/nebula/nebula_density.h"
#include "techniques/nebula/nebula_render.h"

namespace prism::nebula {

inline NebulaModel smallCloud(std::string filters, int starCount) {
  NebulaModel m;
  NoiseParameters noise;
  noise.resolution = 24;
  noise.seed = 7;
  m.density = generateFbm(noise, 0);
  m.extinction = 3.0;
  m.scattering = 1.0;
  m.filters = std::move(filters);
  const NebulaStar stars[] = {{{0.5, 0.55, 0.45}, 12000.0, 1.0},  // inside the cloud
                              {{0.3, 0.4, 0.6}, 4000.0, 0.6},
                              {{0.7, 0.3, 0.3}, 25000.0, 0.8},
                              {{1.6, 0.2, 0.5}, 30000.0, 3.0},    // outside the cube
                              {{0.2, 0.8, 0.2}, 8000.0, 0.5}};
  for (int i = 0; i < starCount; ++i) m.stars.push_back(stars[i]);
  m.camera.width = m.camera.height = 32;
  return m;
}

}  // namespace prism::nebula
