// Warnings for a nebula that renders black although the model is valid: nothing in it gives
// light, or its lines glow nowhere. One line each for stderr, empty when the nebula gives light;
// `nebula render`, `nebula sweep` and a scene's nebula print them before the work.
#pragma once

#include <string>

#include "techniques/nebula/nebula_render.h"

namespace prism::nebula {

// Empty, or why the model's emission lines glow nowhere: ionisation zones with no star of
// luminosity above 0 to ionise the gas (a valid model, whose lines a user asked for and would not
// see: the image had them all black, with no word).
std::string unlitLinesWarning(const NebulaModel& model);

// Empty, or why the nebula gives no light at all and its image comes out black: no star light to
// scatter (no star, none of luminosity above 0, or scattering 0) and no line to glow (emission 0,
// no line of strength above 0, or lines only outside every filter's passband). A valid model; a
// new-user review rendered such ones black with no word. Says nothing where unlitLinesWarning does.
std::string darkNebulaWarning(const NebulaRenderer& renderer);

}  // namespace prism::nebula
