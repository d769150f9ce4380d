// The viewer's panels, in the order the interface shows them (the techniques' after the
// materials): one file each, <name>_panel.cpp (a technique's in its own folder,
// techniques/<name>/viewer/, registered by its prism_technique() call).
#pragma once

#include <memory>
#include <vector>

#include "viewer/panel.h"

namespace prism::viewer {

class Viewer;

std::unique_ptr<Panel> makeCameraPanel();     // field of view, reset
std::unique_ptr<Panel> makeSpectralPanel();   // the left view's spectral settings, the spectra plot
std::unique_ptr<Panel> makeSplitPanel();      // the A/B split: the right view's settings, the heat map
std::unique_ptr<Panel> makeLightsPanel();     // each light's SPD, intensity and direction
std::unique_ptr<Panel> makeMaterialsPanel();  // one material's colour, roughness, metal, reflectance
std::vector<std::unique_ptr<Panel>> makeTechniquePanels();  // every technique's, in registration order
std::unique_ptr<Panel> makeDisplayPanel();    // tone map, exposure, white balance, display
std::unique_ptr<Panel> makeFilesPanel(Viewer& viewer);  // screenshots, settings files, shader reload

}  // namespace prism::viewer
