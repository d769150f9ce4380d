// Which lights get a shadow map and how each sees the scene: directional lights an orthographic
// view fitted around the scene's bounding sphere, spot lights a perspective view over their
// outer cone, point lights six perspective faces (shared::pointShadowFromWorld, a cube map's
// faces as layers of the same array). One layer per view in the shadow map array, in light order.
#pragma once

#include <vector>

#include <glm/glm.hpp>

#include "scene/scene.h"

namespace prism::render {

struct ShadowView {
  int lightIndex = 0;
  int layer = 0;
  glm::mat4 viewProjection{1.0f};  // world → light clip space
  float normalOffsetM = 0.0f;      // receivers are offset along their normal by this much
  float depthBias = 0.0f;          // in the map's [0, 1] depth
  glm::vec3 pointProjection{0.0f};  // point lights: shared::pointShadowProjection of the faces
};

std::vector<ShadowView> planShadowViews(const Scene& scene, int mapSize);

}  // namespace prism::render
