#include "render/shadow_views.h"

#include <algorithm>
#include <cmath>

#include <glm/gtc/matrix_transform.hpp>

#include "render/shared_shading.h"

namespace prism::render {
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

}  // namespace

std::vector<ShadowView> planShadowViews(const Scene& scene, int mapSize) {
  Bounds bounds = sceneBounds(scene);
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
      view.viewProjection = projection * lightView;
      float texelM = 2.0f * radius / size;
      view.normalOffsetM = 1.5f * texelM;
      view.depthBias = 1.0f / size;  // one texel's width of depth: the range is 2·radius deep
    } else {
      float distance = glm::length(centre - light.position);
      const DepthRange range = depthRange(distance, radius);
      glm::mat4 lightView =
          glm::lookAt(light.position, light.position + direction, upFor(direction));
      float fov = 2.0f * glm::radians(std::min(light.outerConeDeg + 2.0f, 89.0f));
      glm::mat4 projection = glm::perspective(fov, 1.0f, range.nearM, range.farM);
      view.viewProjection = projection * lightView;
      float texelM = 2.0f * distance * std::tan(0.5f * fov) / size;
      view.normalOffsetM = 1.5f * texelM;
      view.depthBias = kPerspectiveDepthBias;
    }
    views.push_back(view);
  }
  return views;
}

}  // namespace prism::render
