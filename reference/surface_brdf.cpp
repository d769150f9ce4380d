#include "reference/surface_brdf.h"

#include <algorithm>
#include <cmath>

#include "reference/path_medium.h"
#include "shared_cpp.h"

namespace prism::shared {
#include "brdf.glsl"
}  // namespace prism::shared

namespace prism::reference {
namespace {

using glm::vec3;
using glm::vec4;
using shared::kPi;

float specularShare(const SurfaceHit& hit, bool conductor) {
  return hit.lambertian ? 0.0f : conductor ? 1.0f : 0.25f + 0.75f * hit.metallic;
}

float ggxAlpha(const SurfaceHit& hit) {
  const float r = std::max(hit.roughness, 0.02f);  // as microfacetTerms clamps it
  return r * r;
}

}  // namespace

vec4 brdfCos(const SurfaceHit& hit, bool conductor, const vec3& v, const vec3& l, const vec4& albedoOrN,
             const vec4& k) {
  shared::MicrofacetTerms terms = shared::microfacetTerms(hit.normalW, v, l, hit.roughness);
  if (hit.lambertian) terms = shared::lambertianTerms(terms);
  return shared::surfaceReflection(terms, conductor, albedoOrN, k, conductor ? 1.0f : hit.metallic);
}

vec4 surfaceResponse(const SurfaceHit& hit, bool conductor, const vec3& v, const vec3& l, const vec4& albedoOrN,
                     const vec4& k) {
  if (glm::dot(l, hit.geometricNormalW) <= 0.0f || glm::dot(l, hit.normalW) <= 0.0f) return vec4(0.0f);
  return brdfCos(hit, conductor, v, l, albedoOrN, k);
}

float brdfPdf(const SurfaceHit& hit, bool conductor, const vec3& v, const vec3& l) {
  const vec3& n = hit.normalW;
  const float share = specularShare(hit, conductor);
  const vec3 h = glm::normalize(v + l);
  const float nDotH = std::max(glm::dot(n, h), 0.0f);
  const vec3 nCrossH = glm::cross(n, h);
  const float vDotH = std::max(glm::dot(v, h), 1e-6f);
  const float pdfSpecular =
      shared::ggxDistribution(nDotH, glm::dot(nCrossH, nCrossH), ggxAlpha(hit)) * nDotH / (4.0f * vDotH);
  const float pdfDiffuse = std::max(glm::dot(n, l), 0.0f) / kPi;
  return share * pdfSpecular + (1.0f - share) * pdfDiffuse;
}

std::optional<BrdfSample> sampleBrdf(const SurfaceHit& hit, bool conductor, const vec3& v, const vec4& albedoOrN,
                                     const vec4& k, float u1, float u2, float uLobe) {
  const vec3& n = hit.normalW;
  const float alpha = ggxAlpha(hit);
  vec3 t, b;
  orthonormalFrame(n, t, b);
  vec3 l;
  if (uLobe < specularShare(hit, conductor)) {
    // GGX normal distribution D(h)·(n·h) (Walter et al. 2007, Eq. 35–36), then reflect.
    const float phi = 2.0f * kPi * u1;
    const float cos2 = (1.0f - u2) / (1.0f + (alpha * alpha - 1.0f) * u2);
    const float cosTheta = std::sqrt(cos2), sinTheta = std::sqrt(std::max(0.0f, 1.0f - cos2));
    const vec3 h = t * (sinTheta * std::cos(phi)) + b * (sinTheta * std::sin(phi)) + n * cosTheta;
    l = 2.0f * glm::dot(v, h) * h - v;
  } else {
    // Cosine-weighted hemisphere (Malley's method).
    const float radius = std::sqrt(u1), phi = 2.0f * kPi * u2;
    l = t * (radius * std::cos(phi)) + b * (radius * std::sin(phi)) + n * std::sqrt(std::max(0.0f, 1.0f - u1));
  }
  if (glm::dot(n, l) <= 0.0f || glm::dot(l, hit.geometricNormalW) <= 0.0f) return std::nullopt;
  BrdfSample s;
  s.l = glm::normalize(l);
  s.pdf = brdfPdf(hit, conductor, v, s.l);
  if (!(s.pdf > 0.0f)) return std::nullopt;
  s.weight = brdfCos(hit, conductor, v, s.l, albedoOrN, k) / s.pdf;
  return s;
}

}  // namespace prism::reference
