// View and projection matrices of the scene camera (OpenGL conventions: right-handed view space
// looking down −z, clip depth −1..1), shared by the G-buffer pass, the lighting pass's position
// reconstruction and the CPU twin.
#pragma once

#include <glm/glm.hpp>

#include "scene/scene.h"

namespace prism {

struct CameraTransform {
  glm::mat4 view{1.0f};
  glm::mat4 projection{1.0f};
  glm::mat4 viewProjection{1.0f};
  glm::mat4 inverseViewProjection{1.0f};
  glm::vec3 position{0.0f};
};

CameraTransform cameraTransform(const Camera& camera, int width, int height);

}  // namespace prism
