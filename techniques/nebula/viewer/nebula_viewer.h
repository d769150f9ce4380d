// The nebula in the viewer (registered by techniques/nebula/CMakeLists.txt): its panel and its
// script keys. The pass follows any change of the section on the next frame (it keys its
// precomputation and its march on the section), so both only edit the scene's section.
#pragma once

#include <memory>
#include <string>

#include "viewer/panel.h"
#include "viewer/technique_settings.h"

namespace prism::viewer {

// The method (any of the five), basis size, steps, filters (Hubble palette
// or CIE 1931) and their passbands, intensity, extinction, scattering, emission, the ionisation
// zones, the density's noise, and the stars (add, remove, move, temperature, luminosity, whether
// they light the surfaces).
std::unique_ptr<Panel> makeNebulaPanel();
// nebula.method M, nebula.basis N, nebula.steps N, nebula.filters F, nebula.intensity X,
// nebula.extinction X, nebula.scattering X, nebula.emission X, nebula.light_surfaces on|off,
// nebula.ionisation on|off,
// nebula.ionisation.front_radius R, nebula.ionisation.front_width W (either turns the zones on),
// per channel c nebula.passband.c.shift_nm|width, and per star i (from 0)
// nebula.star.i.temperature K, nebula.star.i.luminosity L, nebula.star.i.position X,Y,Z
// (a TechniqueSetKey).
bool setNebulaKey(Scene& scene, const std::string& key, const std::string& value);

}  // namespace prism::viewer
