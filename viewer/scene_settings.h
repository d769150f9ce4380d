// The scene's lights and materials as `set KEY VALUE` keys of the viewer's script: each light's
// light.N.spd NAME, light.N.intensity X, light.N.direction X,Y,Z, light.N.position X,Y,Z (point
// and spot lights) and light.N.shadows on|off; each material's material.NAME.base-colour R,G,B,
// material.NAME.roughness X and material.NAME.metallic X. The lights and materials panels edit the
// same fields.
#pragma once

#include <string>

#include "scene/scene.h"

namespace prism::viewer {

// False when the key is not a light's or a material's (light.*.*, material.*.*); Error naming the
// key when it is one but the light, the material, the setting or the value is not.
bool applySceneSetting(Scene& scene, const std::string& key, const std::string& value);

}  // namespace prism::viewer
