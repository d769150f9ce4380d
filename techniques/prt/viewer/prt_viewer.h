// PRT in the viewer (registered by techniques/prt/CMakeLists.txt): its panel and its script keys.
// The forward pass follows any change of the section on the next frame (it keys its projections
// on the section), so both only edit the scene's section.
#pragma once

#include <memory>
#include <string>

#include "viewer/panel.h"
#include "viewer/technique_settings.h"

namespace prism::viewer {

// The mode (spectral, RGB-PRT, 5 nm reference), the basis size m, the environment's illuminant,
// shape, luminance and rotation about the zenith, or the spectral sky's sun.
std::unique_ptr<Panel> makePrtPanel();
// prt.mode M, prt.basis N, prt.illuminant NAME, prt.rotation DEG, and under the spectral sky
// prt.sun-elevation DEG, prt.sun-azimuth DEG (a TechniqueSetKey).
bool setPrtKey(Scene& scene, const std::string& key, const std::string& value);

}  // namespace prism::viewer
