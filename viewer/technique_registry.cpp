// The techniques' panels and script keys, from the list their prism_technique() calls generate.
#include "viewer/panels.h"
#include "viewer/technique_settings.h"

#include "technique_viewers.h"

namespace prism::viewer {

std::vector<std::unique_ptr<Panel>> makeTechniquePanels() {
  std::vector<std::unique_ptr<Panel>> panels;
  for (auto make : kTechniquePanels) panels.push_back(make());
  return panels;
}

std::span<const TechniqueSetKey> techniqueSetKeys() { return kTechniqueSetKeys; }

}  // namespace prism::viewer
