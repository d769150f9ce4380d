#include "viewer/camera_controller.h"

#include <algorithm>
#include <cmath>

namespace prism::viewer {
namespace {

constexpr float kMaxPitch = 1.55f;  // ≈ 89°: the view never reaches the poles, where yaw is undefined

// v rotated by yaw about +y and by pitch about the horizontal axis across it.
glm::vec3 turned(const glm::vec3& v, float yaw, float pitch) {
  float length = glm::length(v);
  float currentPitch = std::asin(std::clamp(v.y / length, -1.0f, 1.0f));
  float currentYaw = std::atan2(v.x, v.z);
  float p = std::clamp(currentPitch + pitch, -kMaxPitch, kMaxPitch);
  float y = currentYaw + yaw;
  return length * glm::vec3(std::cos(p) * std::sin(y), std::sin(p), std::cos(p) * std::cos(y));
}

}  // namespace

glm::vec3 CameraController::forward() const { return glm::normalize(mCamera.target - mCamera.position); }

glm::vec3 CameraController::right() const {
  glm::vec3 r = glm::cross(forward(), glm::vec3(0.0f, 1.0f, 0.0f));
  // Looking straight up or down: the camera's own up vector decides what is right.
  if (glm::dot(r, r) < 1e-10f) r = glm::cross(forward(), mCamera.up);
  if (glm::dot(r, r) < 1e-10f) r = glm::vec3(1.0f, 0.0f, 0.0f);
  return glm::normalize(r);
}

void CameraController::setFieldOfView(float verticalDeg) {
  mCamera.verticalFovDeg = std::clamp(verticalDeg, kMinFieldOfViewDeg, kMaxFieldOfViewDeg);
}

void CameraController::orbit(float yaw, float pitch) {
  // The camera moves on the sphere about the target.
  mCamera.position = mCamera.target + turned(mCamera.position - mCamera.target, yaw, pitch);
  mCamera.up = glm::vec3(0.0f, 1.0f, 0.0f);
}

void CameraController::dolly(float fraction) {
  glm::vec3 offset = mCamera.position - mCamera.target;
  float distance = glm::length(offset);
  float next = std::max(distance * (1.0f - std::clamp(fraction, -4.0f, 0.9f)), 1e-3f);
  mCamera.position = mCamera.target + offset * (next / distance);
}

void CameraController::pan(float right, float up) {
  float distance = glm::length(mCamera.target - mCamera.position);
  glm::vec3 f = forward(), r = this->right();
  glm::vec3 u = glm::cross(r, f);
  glm::vec3 move = (r * right + u * up) * distance;
  mCamera.position += move;
  mCamera.target += move;
}

void CameraController::fly(const glm::vec3& rightUpForwardM) {
  glm::vec3 f = forward(), r = right();
  glm::vec3 u = glm::cross(r, f);
  glm::vec3 move = r * rightUpForwardM.x + u * rightUpForwardM.y + f * rightUpForwardM.z;
  mCamera.position += move;
  mCamera.target += move;
}

void CameraController::look(float yaw, float pitch) {
  mCamera.target = mCamera.position + turned(mCamera.target - mCamera.position, yaw, pitch);
  mCamera.up = glm::vec3(0.0f, 1.0f, 0.0f);
}

}  // namespace prism::viewer
