// Reading a scene file (JSON, documented in docs/scene-format.md) into a Scene.
//
// Everything a file names is checked before it is used, and every failure is one prism::Error
// line, "<scene file>: <JSON pointer>: <what>", for example
//   scenes/x.json: /lights/0/intensity: expected a number > 0, got "bright"
// (malformed JSON: "<scene file>:<line>:<column>: malformed JSON: <what>"). Errors inside a
// file the scene names follow the pointer, e.g. "… /objects/2/gltf: model.gltf: /meshes/0/…".
// Files the scene names (spectra, textures, glTF models and their buffers and images) must be
// relative paths without ".." that stay inside the scene file's folder, symbolic links resolved.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "scene/scene.h"
#include "spectral/spectrum.h"

namespace prism {

Scene loadScene(const std::filesystem::path& file);

// With overrides, as the CLI's `--set PATH=VALUE`, applied in order to the parsed JSON before
// it is checked: PATH is dot-separated object keys and array indices ("camera.ev100",
// "lights.0.intensity", "materials.red.roughness"); VALUE is parsed as JSON, and taken as a
// string when it is not JSON ("lights.0.spd=blackbody:2700"). Every step but the last must
// exist; the last may add a key to an object (checked like any other key). Error
// "<scene file>: <pointer>: --set <PATH=VALUE>: <what>" for a path that leads nowhere.
Scene loadScene(const std::filesystem::path& file, const std::vector<std::string>& sets);

// A light's SPD divided by its luminousIntegral (spectral/observer.h), so that it is 1, as every
// light in a Scene is (scene/scene.h).
// Error when a value is negative or not finite, or when there is no luminous power.
Spectrum normalisedLightSpectrum(const Spectrum& spd);

// Makes the scene's technique lights what their sections say (the sky's sun: the solar spectrum
// at the top of the atmosphere, its illuminance there, about 133 klux), normalised like every light
// and tagged with their technique (Light::technique): on load, and again after an editor changed a
// section (the sun's angles; PRT's sun disc switched on adds its light, off takes it away).
void applyTechniqueLights(Scene& scene);

}  // namespace prism
