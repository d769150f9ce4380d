#include "render/shadow_views.h"

#include <algorithm>
#include <cmath>

#include <glm/gtc/matrix_transform.hpp>

#include "render/frame_settings.h"
#include "render/shared_shading.h"

namespace prism::render {
static_assert(kShadowCascadesMax == shared::kMaxShadowCascades);

namespace {

// An up vector not parallel to the view direction.
glm::vec3 upFor(const glm::vec3& direction) {
  return std::abs(direction.y) > 0.99f ? glm::vec3(0.0f, 0.0f, 1.0f) : glm::vec3(0.0f, 1.0f, 0.0f);
}

// A perspective view's depth range from a light `distance` away from the centre of the scene's
// bounding sphere: the sphere, from no nearer than 5 cm, or than a hundredth of the range's far
// end in a scene smaller than that makes 5 cm (what lies nearer the light casts no shadow: a
// fixed 5 cm left a scene in centimetres without its point and spot lights' shadows). A range
// reaching 5 m or more keeps the 5 cm, as every example scene and test fixture does.
struct DepthRange {
  float nearM, farM;
};
DepthRange depthRange(float distance, float radius) {
  const float farM = distance + radius;
  const float nearM = std::max(std::min(0.05f, 0.01f * farM), distance - radius);
  return {nearM, std::max(nearM * 2.0f, farM)};
}

constexpr float kPerspectiveDepthBias = 5e-5f;  // in the map's [0, 1] depth

// The windows of a directional light's cascades over its whole-scene map (`wholeScene`, whose
// x, y span the scene's bounding sphere, radius `radius` around `centre`): the camera's view
// between the depths of its nearest and farthest sight of the sphere split into `count` slices,
// nearer ones thinner (Zhang et al. 2006's practical split, three quarters logarithmic); each of
// the first count − 1 is a square around the slice's bounding sphere, its radius rounded up to a
// power of 2^(1/8) and its centre moved in whole texels of its own, so that the texels stay put
// while the camera moves within a step; the last window is the whole map. A slice no smaller
// than the whole map takes the whole map, and so do those beyond it. A window's scale is at most
// 2²¹ / mapSize: its depth bias, one of its texels in the whole scene's depth range, stays eight
// float steps below 1 or more.
std::vector<glm::vec4> cascadeWindows(const glm::mat4& wholeScene, const glm::vec3& centre, float radius,
                                      const ShadowCascading& cascading, int mapSize) {
  const Camera& camera = cascading.camera;
  const int count = cascading.count;
  std::vector<glm::vec4> windows(static_cast<std::size_t>(count), glm::vec4(0.0f, 0.0f, 1.0f, 0.0f));
  glm::vec3 forward = camera.target - camera.position;
  if (!(glm::length(forward) > 0.0f)) return windows;
  forward = glm::normalize(forward);
  const float slope = std::tan(0.5f * glm::radians(camera.verticalFovDeg)) *
                      std::sqrt(1.0f + cascading.aspect * cascading.aspect);  // a slice's half-diagonal over its depth
  // A point at distance d in view lies at a depth from d / √(1 + slope²) (in a corner) to d.
  const float toCentre = glm::length(centre - camera.position);
  const float nearM = std::max(camera.nearPlane, (toCentre - radius) / std::sqrt(1.0f + slope * slope));
  const float farM = std::max(std::min(camera.farPlane, toCentre + radius), 1.001f * nearM);
  const float maxScale = std::ldexp(1.0f, 21) / static_cast<float>(mapSize);
  auto split = [&](int i) {
    const float t = static_cast<float>(i) / static_cast<float>(count);
    return 0.75f * nearM * std::pow(farM / nearM, t) + 0.25f * (nearM + (farM - nearM) * t);
  };
  for (int i = 0; i + 1 < count; ++i) {
    const float d0 = split(i), d1 = split(i + 1);
    // The sphere through the slice's eight corners, its centre on the view's axis.
    const float along = std::min(0.5f * (d0 + d1) * (1.0f + slope * slope), d1);
    const float sliceRadius = std::exp2(
        std::ceil(8.0f * std::log2(std::max(std::hypot(along - d0, slope * d0), std::hypot(d1 - along, slope * d1)))) /
        8.0f);
    const float scale = std::min(radius / sliceRadius, maxScale);
    if (!(scale > 1.0f)) break;  // this slice and those beyond it need no finer map than the whole
    const glm::vec4 clip = wholeScene * glm::vec4(camera.position + forward * along, 1.0f);
    const float texel = 2.0f / (scale * static_cast<float>(mapSize));  // the window's texel in the whole map's clip units
    windows[static_cast<std::size_t>(i)] =
        glm::vec4(std::round(clip.x / texel) * texel, std::round(clip.y / texel) * texel, scale, 0.0f);
  }
  return windows;
}

}  // namespace

std::vector<ShadowView> planShadowViews(const Scene& scene, int mapSize, const ShadowCascading& cascading) {
  return planShadowViews(scene, sceneBounds(scene), mapSize, cascading);
}

std::vector<ShadowView> planShadowViews(const Scene& scene, const Bounds& bounds, int mapSize,
                                        const ShadowCascading& cascading) {
  glm::vec3 centre = 0.5f * (bounds.min + bounds.max);
  float radius = std::max(0.5f * glm::length(bounds.max - bounds.min), 1e-3f);
  float size = static_cast<float>(mapSize);

  std::vector<ShadowView> views;
  for (std::size_t i = 0; i < scene.lights.size(); ++i) {
    const Light& light = scene.lights[i];
    if (!light.castsShadows) continue;
    if (light.type == LightType::Point) {
      // Depth range, normal offset and bias as a spot's, the texel taken at the farther of the scene's centre and its radius (a light inside the scene
      // lights surfaces about a radius away).
      float distance = glm::length(centre - light.position);
      const DepthRange range = depthRange(distance, radius);
      const glm::vec3 projection = shared::pointShadowProjection(range.nearM, range.farM, mapSize);
      float texelM = 2.0f * std::max(distance, radius) / (projection.x * size);
      for (int face = 0; face < 6; ++face) {
        ShadowView view;
        view.lightIndex = static_cast<int>(i);
        view.layer = static_cast<int>(views.size());
        view.viewProjection = shared::pointShadowFromWorld(light.position, face, projection);
        view.normalOffsetM = 1.5f * texelM;
        view.depthBias = kPerspectiveDepthBias;
        view.pointProjection = projection;
        view.lightFromWorld = view.viewProjection;
        views.push_back(view);
      }
      continue;
    }
    ShadowView view;
    view.lightIndex = static_cast<int>(i);
    view.layer = static_cast<int>(views.size());
    glm::vec3 direction = glm::normalize(light.direction);
    if (light.type == LightType::Directional) {
      glm::vec3 eye = centre - direction * (2.0f * radius);
      glm::mat4 lightView = glm::lookAt(eye, centre, upFor(direction));
      glm::mat4 projection = glm::ortho(-radius, radius, -radius, radius, radius, 3.0f * radius);
      view.lightFromWorld = projection * lightView;
      float texelM = 2.0f * radius / size;
      view.normalOffsetM = 1.5f * texelM;
      view.depthBias = 1.0f / size;  // one texel's width of depth: the range is 2·radius deep
      bool wholeMapDrawn = false;
      for (const glm::vec4& window : cascadeWindows(view.lightFromWorld, centre, radius, cascading, mapSize)) {
        view.layer = static_cast<int>(views.size());
        view.cascadeWindow = window;
        view.viewProjection = shared::shadowCascadeFromWorld(view.lightFromWorld, window);
        const bool wholeMap = window == glm::vec4(0.0f, 0.0f, 1.0f, 0.0f);
        view.drawn = !(wholeMap && wholeMapDrawn);
        wholeMapDrawn = wholeMapDrawn || wholeMap;
        views.push_back(view);
      }
      continue;
    }
    float distance = glm::length(centre - light.position);
    const DepthRange range = depthRange(distance, radius);
    glm::mat4 lightView = glm::lookAt(light.position, light.position + direction, upFor(direction));
    float fov = 2.0f * glm::radians(std::min(light.outerConeDeg + 2.0f, 89.0f));
    glm::mat4 projection = glm::perspective(fov, 1.0f, range.nearM, range.farM);
    view.viewProjection = projection * lightView;
    view.lightFromWorld = view.viewProjection;
    float texelM = 2.0f * distance * std::tan(0.5f * fov) / size;
    view.normalOffsetM = 1.5f * texelM;
    view.depthBias = kPerspectiveDepthBias;
    views.push_back(view);
  }
  return views;
}

}  // namespace prism::render
