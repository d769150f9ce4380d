// The participating medium as the reference path tracer crosses it: which medium the paths are
// in, its coefficients at a path's four wavelengths, the part of a ray inside its region, and
// Henyey & Greenstein's phase function with its sampling; and the orthonormal frame around a
// direction in which both the phase function and the BRDF draw their directions.
#pragma once

#include <optional>

#include <glm/glm.hpp>

#include "scene/scene.h"

namespace prism::reference {

// The medium's coefficients at a path's four wavelengths.
struct MediumAt {
  glm::vec4 sigmaS{0.0f};
  glm::vec4 sigmaT{0.0f};
};

// The medium the paths cross: a technique's (the water's: everything below its surface), else
// the scene's, if any.
std::optional<HomogeneousMedium> effectiveMedium(const Scene& scene);

// The part of the ray [tMin, tMax] inside the medium's region (slab test); empty when
// tEnter >= tExit.
void mediumInterval(const HomogeneousMedium& medium, const glm::vec3& origin, const glm::vec3& direction, float tMin,
                    float tMax, float& tEnter, float& tExit);

// Henyey & Greenstein 1941's phase function of the angle between the light's direction of travel
// before and after scattering, per steradian.
float henyeyGreenstein(float cosTheta, float g);

// A direction of travel after scattering, drawn from the phase function itself (its inverse CDF,
// pbrt-v3 §15.2.3), so that the path's weight does not change.
glm::vec3 sampleHenyeyGreenstein(const glm::vec3& travel, float g, float u1, float u2);

// An orthonormal frame t, b around unit n (Duff et al. 2017, "Building an Orthonormal Basis,
// Revisited").
void orthonormalFrame(const glm::vec3& n, glm::vec3& t, glm::vec3& b);

}  // namespace prism::reference
