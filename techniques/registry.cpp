#include "techniques/registry.h"

#include "technique_sections.h"
#include "techniques/atmosphere/sky_strategy.h"

namespace prism {

std::span<const TechniqueSectionParser> techniqueSectionParsers() {
  return kTechniqueSectionParsers;
}

TechniqueWavelengths optimisedWavelengths(const TechniqueSections& sections) {
  for (const auto& section : sections.all()) {
    if (std::optional<TechniqueWavelengths> own = section->optimisedWavelengths()) return *own;
  }
  atmosphere::OptimisedWavelengths set = atmosphere::loadOptimisedWavelengths("aerosols");
  return {set.lambdaNm, set.weights};
}

}  // namespace prism
