// A light's SPD replaced from the lights panel or the script: normalised and checked as the scene
// loader does it, its label kept for the interface and the errors.
#pragma once

#include <string>

#include "scene/scene.h"
#include "spectral/spectrum.h"

namespace prism::viewer {

// Error "LABEL: what" when the spectrum cannot light anything; the light is then unchanged.
void setLightSpectrum(Light& light, const Spectrum& spd, const std::string& label);
// A spectrum's CSV file (zero beyond its rows), labelled "csv:PATH".
void setLightSpdFromCsv(Light& light, const std::string& path);
// A named illuminant, a parametric one ("blackbody:3000", "led:450:20"), or a name ending in .csv,
// a CSV file labelled as setLightSpdFromCsv labels it (lampSpectrum).
void setLightSpd(Light& light, const std::string& name);

}  // namespace prism::viewer
