// The reference path tracer's aim at a technique's distant environment (PRT's map or sky, the
// spectral sky): the sphere of directions cut into cells of equal solid angle (cos θ about world
// y, and azimuth), each weighed by the light the environment sends from it as the observer sees
// it (a few wavelengths at a few points of the cell), a cell drawn ∝ its weight, then a direction
// uniform in it. A bright patch of a map (its sun) is then found by next-event estimation, not
// only by a BRDF sample that happens to point at it; the path tracer weighs the two by multiple
// importance sampling, so a light smaller than a cell (the spectral sky's sun disc) costs noise,
// never bias.
#pragma once

#include <vector>

#include <glm/glm.hpp>

#include "spectral/observer.h"
#include "techniques/technique_section.h"

namespace prism::reference {

class EnvironmentSampler {
 public:
  // Evaluates the environment at kRows × kCols × 4 points and 21 wavelengths, on `threads`
  // threads (0: all).
  EnvironmentSampler(const TechniqueEnvironment& environment, const Observer& observer, unsigned threads);

  // True when the environment sends no light the observer sees (nothing to aim at).
  bool empty() const { return mCumulative.empty(); }
  struct Direction {
    glm::vec3 towards{0.0f};  // unit, world space, towards where the light comes from
    float pdf = 0.0f;         // per steradian
  };
  // A direction drawn from three uniform numbers in [0, 1): u0 picks the cell (a double, as
  // EmitterSampler's), u1 and u2 the direction in it. PRISM_CHECKs !empty().
  Direction sample(double u0, float u1, float u2) const;
  // The density per steradian with which sample() draws unit `towards` (0 when empty()).
  float pdf(const glm::vec3& towards) const;

  static constexpr int kRows = 64;   // of cos θ, from 1 (world +y) to −1
  static constexpr int kCols = 128;  // of azimuth

 private:
  std::vector<double> mCumulative;  // running sum of the cells' weights, row-major
  std::vector<float> mPdf;          // per cell, per steradian
};

}  // namespace prism::reference
