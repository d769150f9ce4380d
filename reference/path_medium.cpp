#include "reference/path_medium.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <utility>

namespace prism::reference {

using glm::vec3;

std::optional<HomogeneousMedium> effectiveMedium(const Scene& scene) {
  if (std::optional<TechniqueMedium> m = scene.techniques.medium(scene.camera.position))
    return HomogeneousMedium{m->sigmaA, m->sigmaS, m->g, Bounds{m->regionMin, m->regionMax}};
  return scene.medium;
}

void mediumInterval(const HomogeneousMedium& medium, const vec3& origin, const vec3& direction, float tMin,
                    float tMax, float& tEnter, float& tExit) {
  tEnter = tMin;
  tExit = tMax;
  if (!medium.region) return;
  for (int a = 0; a < 3; ++a) {
    float inverse = 1.0f / direction[a];
    float t0 = (medium.region->min[a] - origin[a]) * inverse;
    float t1 = (medium.region->max[a] - origin[a]) * inverse;
    if (t0 > t1) std::swap(t0, t1);
    if (std::isnan(t0) || std::isnan(t1)) {  // parallel to the slab, on its boundary plane
      if (origin[a] < medium.region->min[a] || origin[a] > medium.region->max[a]) tExit = tEnter;
      continue;
    }
    tEnter = std::max(tEnter, t0);
    tExit = std::min(tExit, t1);
  }
}

float henyeyGreenstein(float cosTheta, float g) {
  float d = 1.0f + g * g - 2.0f * g * cosTheta;
  return (1.0f - g * g) / (4.0f * std::numbers::pi_v<float> * d * std::sqrt(d));
}

vec3 sampleHenyeyGreenstein(const vec3& travel, float g, float u1, float u2) {
  float cosTheta;
  if (std::abs(g) < 1e-3f) {
    cosTheta = 1.0f - 2.0f * u1;
  } else {
    float q = (1.0f - g * g) / (1.0f - g + 2.0f * g * u1);
    cosTheta = std::clamp((1.0f + g * g - q * q) / (2.0f * g), -1.0f, 1.0f);
  }
  float sinTheta = std::sqrt(std::max(0.0f, 1.0f - cosTheta * cosTheta));
  float phi = 2.0f * std::numbers::pi_v<float> * u2;
  vec3 t, b;
  orthonormalFrame(travel, t, b);
  return glm::normalize(t * (sinTheta * std::cos(phi)) + b * (sinTheta * std::sin(phi)) + travel * cosTheta);
}

void orthonormalFrame(const vec3& n, vec3& t, vec3& b) {
  float sign = std::copysign(1.0f, n.z);
  float a = -1.0f / (sign + n.z);
  float c = n.x * n.y * a;
  t = vec3(1.0f + sign * n.x * n.x * a, sign * c, -sign * n.x);
  b = vec3(c, sign + n.y * n.y * a, -n.y);
}

}  // namespace prism::reference
