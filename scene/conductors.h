// Measured complex indices of refraction, n + ik relative to air, for the conductors (and the
// two absorbing dielectrics) a scene material may name. Data: data/metals_ior.csv (Ag, Al, Au,
// Cu) and data/conductors_extra_ior.csv (CuZn brass, MgO, TiO2), both pbrt-v4's measured sets
// (data/SOURCES.md).
//
// Extrapolation: Clamp. The tables cover about 290–900 nm, but MgO stops at 767.68 nm; beyond a
// table's ends its last measured n and k are the best estimate of the next (n and k of these
// materials vary slowly there), where zero would mean a perfect mirror (k = 0, n = 0).
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "scene/scene.h"

namespace prism {

// Error "unknown conductor 'X' (known: Ag, Al, …)" when the name is not in listConductors().
ConductorIor conductorIor(std::string_view name);
std::vector<std::string> listConductors();

}  // namespace prism
