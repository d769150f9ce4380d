// What every path of the reference path tracer draws and weighs with: its own stream of uniform
// numbers (PathRandom), and the power heuristic that weighs two ways of drawing one direction
// (a BRDF's or phase function's sample against an emitter or environment aimed at).
#pragma once

#include <cstdint>

#include "shared_cpp.h"

namespace prism::shared {
#include "random.glsl"
}  // namespace prism::shared

namespace prism::reference {

// Independent uniform numbers for one path: the PCG hash of a counter (random.glsl), seeded by
// pixel, sample and image seed, so that the image does not depend on the thread count.
class PathRandom {
 public:
  PathRandom(std::uint32_t pixel, std::uint32_t sample, std::uint32_t seed)
      : mSeed(shared::pcgHash(pixel ^ shared::pcgHash(sample ^ shared::pcgHash(seed)))) {}
  std::uint32_t seed() const { return mSeed; }
  float next() { return shared::randomFloat(mSeed, mIndex++); }
  // Uniform in [0, 1) to 2⁻⁴⁸ rather than next()'s 2⁻²⁴: a choice among up to millions of
  // emitting triangles or environment cells, whose shares can be far below 2⁻²⁴.
  double nextFine() {
    const double coarse = next();
    return coarse + static_cast<double>(next()) * 0x1p-24;
  }

 private:
  std::uint32_t mSeed;
  std::uint32_t mIndex = 0;
};

// The power heuristic (Veach 1997, β = 2): the weight of a sample drawn with density `chosen`
// where another strategy would have drawn it with density `other`. As 1/(1 + (other/chosen)²),
// not chosen²/(chosen² + other²): a density past 1e19 (an emitter seen edge-on) squares to ∞.
inline float powerHeuristic(float chosen, float other) {
  if (!(chosen > 0.0f)) return 0.0f;
  const float ratio = other / chosen;
  return 1.0f / (1.0f + ratio * ratio);
}

}  // namespace prism::reference
