// Which lights get a shadow map and how each sees the scene: directional lights an orthographic
// view fitted around the scene's bounding sphere, or cascades of them fitted to slices of the
// camera's view (its texels finest near the camera: one map over a large ground made a small
// object's shadow fade), spot lights a perspective view over their outer cone, point lights six
// perspective faces (shared::pointShadowFromWorld, a cube map's faces as layers of the same
// array). Layers in the shadow map array in light order: a directional light's cascades finest
// first, a point light's faces.
#pragma once

#include <vector>

#include <glm/glm.hpp>

#include "scene/scene.h"

namespace prism::render {

struct ShadowView {
  int lightIndex = 0;
  int layer = 0;
  glm::mat4 viewProjection{1.0f};  // world → the layer's clip space: what the shadow pass renders with
  // Receivers are offset along their normal by this much, and compared with this bias in the
  // map's [0, 1] depth: a directional light's whole-scene map's (a cascade's are these / window.z).
  float normalOffsetM = 0.0f;
  float depthBias = 0.0f;
  glm::vec3 pointProjection{0.0f};  // point lights: shared::pointShadowProjection of the faces
  glm::mat4 lightFromWorld{1.0f};   // GpuLight::shadowFromWorld: directional, the whole-scene map's; spot, viewProjection
  glm::vec4 cascadeWindow{0.0f, 0.0f, 1.0f, 0.0f};  // directional: shared::shadowCascadeFromWorld's window
  // False for a directional light's cascade that collapsed onto the whole map an earlier layer
  // holds (the view's slices no smaller than the scene): its layer is kept, not drawn, not looked up.
  bool drawn = true;
};

// How many layers a directional light's shadow takes (1: the whole scene's map alone; up to
// shared::kMaxShadowCascades, the last always the whole scene's) and the view its cascades are
// fitted to.
struct ShadowCascading {
  int count = 1;
  Camera camera;
  float aspect = 1.0f;  // the image's width over its height
};

std::vector<ShadowView> planShadowViews(const Scene& scene, int mapSize, const ShadowCascading& cascading = {});
// The same with the scene's bounds (sceneBounds) given, as a renderer keeps them.
std::vector<ShadowView> planShadowViews(const Scene& scene, const Bounds& bounds, int mapSize,
                                        const ShadowCascading& cascading);

}  // namespace prism::render
