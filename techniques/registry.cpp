#include "techniques/registry.h"

#include "techniques/atmosphere/atmosphere_section.h"
#include "techniques/atmosphere/sky_strategy.h"
#include "techniques/underwater/water_section.h"

namespace prism {

std::span<const TechniqueSectionParser> techniqueSectionParsers() {
  static const TechniqueSectionParser kParsers[] = {
      {underwater::WaterSection::kKey, &underwater::WaterSection::parse},
      {atmosphere::AtmosphereSection::kKey, &atmosphere::AtmosphereSection::parse},
  };
  return kParsers;
}

TechniqueWavelengths optimisedWavelengths(const TechniqueSections& sections) {
  for (const auto& section : sections.all()) {
    if (std::optional<TechniqueWavelengths> own = section->optimisedWavelengths()) return *own;
  }
  atmosphere::OptimisedWavelengths set = atmosphere::loadOptimisedWavelengths("aerosols");
  return {set.lambdaNm, set.weights};
}

}  // namespace prism
