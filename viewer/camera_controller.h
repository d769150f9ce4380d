// The viewer's camera controls over a scene Camera. Orbit: rotate about the target (yaw about
// world +y, pitch kept off the poles), dolly towards it, pan it with the camera. Fly: move along
// the view's right, up and forward axes and turn the view in place (the target moves with it).
// Pure maths on glm, so tests need no window.
#pragma once

#include <glm/glm.hpp>
#include <glm/gtc/constants.hpp>

#include "scene/scene.h"

namespace prism::viewer {

// The viewer's field of view (vertical, degrees): the panel's and the script's range.
inline constexpr float kMinFieldOfViewDeg = 5.0f;
inline constexpr float kMaxFieldOfViewDeg = 150.0f;

// Radians per degree: the viewer's controls and script take angles in degrees.
constexpr float kDegrees = glm::pi<float>() / 180.0f;

class CameraController {
 public:
  explicit CameraController(const Camera& initial) : mInitial(initial), mCamera(initial) {}

  const Camera& camera() const { return mCamera; }
  void reset() { mCamera = mInitial; }
  void setFieldOfView(float verticalDeg);  // clamped to [kMinFieldOfViewDeg, kMaxFieldOfViewDeg]

  // The camera moves on the sphere about the target, angles in radians: yaw about world +y,
  // pitch positive to rise above the target (the view looks further down).
  void orbit(float yaw, float pitch);
  // Moves the camera a fraction of its distance towards (> 0) or away from the target.
  void dolly(float fraction);
  // Moves camera and target by fractions of the distance along the view's right and up axes.
  void pan(float right, float up);
  // Moves camera and target by metres along the view's right, up and forward axes.
  void fly(const glm::vec3& rightUpForwardM);
  // Turns the view in place (the target swings around the camera): pitch positive looks up.
  void look(float yaw, float pitch);

 private:
  glm::vec3 forward() const;
  glm::vec3 right() const;  // unit, horizontal where it can be
  Camera mInitial;
  Camera mCamera;
};

}  // namespace prism::viewer
