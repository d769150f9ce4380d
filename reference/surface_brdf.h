// The reference path tracer's BRDF at a surface hit — the rasteriser's own model
// (shaders/shared/brdf.glsl: UE4 Cook–Torrance, Lambert, a conductor's spectral Fresnel) — and the
// directions it draws from it: GGX's distribution of normals and the cosine, mixed by the specular
// lobe's share, with that mixture's density, which multiple importance sampling weighs against
// the lights, emitters and environments aimed at.
#pragma once

#include <optional>

#include <glm/glm.hpp>

#include "reference/surface_hit.h"

namespace prism::reference {

// BRDF·cos for light arriving from unit `l`, seen from unit `v`: `albedoOrN` (a conductor's n) and
// `k` at the path's four wavelengths; `conductor`: the hit's material is one.
glm::vec4 brdfCos(const SurfaceHit& hit, bool conductor, const glm::vec3& v, const glm::vec3& l,
                  const glm::vec4& albedoOrN, const glm::vec4& k);

// brdfCos, 0 for light from below the surface (either normal).
glm::vec4 surfaceResponse(const SurfaceHit& hit, bool conductor, const glm::vec3& v, const glm::vec3& l,
                          const glm::vec4& albedoOrN, const glm::vec4& k);

// The density per steradian with which sampleBrdf draws unit `l` (above the surface).
float brdfPdf(const SurfaceHit& hit, bool conductor, const glm::vec3& v, const glm::vec3& l);

struct BrdfSample {
  glm::vec3 l{0.0f};       // unit, towards where the light comes from
  glm::vec4 weight{0.0f};  // brdfCos / pdf
  float pdf = 0.0f;        // brdfPdf
};
// A direction drawn from three uniform numbers in [0, 1): `uLobe` picks the lobe (specular with
// the specular share: all of a conductor's, none of a Lambertian's, ¼ to all with metallic), u1
// and u2 the direction in it. None where the path ends: below either normal, or a zero density.
std::optional<BrdfSample> sampleBrdf(const SurfaceHit& hit, bool conductor, const glm::vec3& v,
                                     const glm::vec4& albedoOrN, const glm::vec4& k, float u1, float u2, float uLobe);

}  // namespace prism::reference
