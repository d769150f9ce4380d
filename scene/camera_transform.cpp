#include "scene/camera_transform.h"

#include <glm/gtc/matrix_transform.hpp>

namespace prism {

CameraTransform cameraTransform(const Camera& camera, int width, int height) {
  CameraTransform t;
  t.position = camera.position;
  t.view = glm::lookAt(camera.position, camera.target, camera.up);
  float aspect = static_cast<float>(width) / static_cast<float>(height);
  t.projection = glm::perspective(glm::radians(camera.verticalFovDeg), aspect, camera.nearPlane,
                                  camera.farPlane);
  t.viewProjection = t.projection * t.view;
  t.inverseViewProjection = glm::inverse(t.viewProjection);
  return t;
}

}  // namespace prism
