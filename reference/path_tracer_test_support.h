// Scenes the path tracer's tests share (path_tracer_test.cpp, path_tracer_emitter_test.cpp): a
// floor filling the view from 3 m above it, and a black emitter of D65.
#pragma once

#include <glm/glm.hpp>

#include "scene/procedural_mesh.h"
#include "scene/scene.h"
#include "spectral/illuminant.h"

namespace prism::reference::test {

// A 20 m floor at y = 0 of `floor`, seen from 3 m straight above with a 30° field of view (far
// plane 500 m: an emitting sphere of 100 m around it is in view).
inline Scene floorSeenFromAbove(const Material& floor) {
  Scene scene;
  scene.camera.position = {0.0f, 3.0f, 0.0f};
  scene.camera.target = {0.0f, 0.0f, 0.0f};
  scene.camera.up = {0.0f, 0.0f, -1.0f};
  scene.camera.verticalFovDeg = 30.0f;
  scene.camera.farPlane = 500.0f;
  scene.materials.push_back(floor);
  scene.meshes.push_back(makePlane({0.0f, 0.0f, 0.0f}, {0.0f, 1.0f, 0.0f}, {20.0f, 20.0f}));
  return scene;
}

// A Lambertian material that reflects nothing and emits D65 of `luminance` cd/m².
inline Material d65Emitter(float luminance) {
  Material m;
  m.lambertian = true;
  m.reflectance = Spectrum::constant(0.0);
  Spectrum d65 = illuminant("D65");
  m.emission = Emission{d65 * (1.0 / luminousIntegral(d65)), luminance};
  return m;
}

}  // namespace prism::reference::test
