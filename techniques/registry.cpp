#include "techniques/registry.h"

#include "techniques/atmosphere/atmosphere_section.h"
#include "techniques/underwater/water_section.h"

namespace prism {

std::span<const TechniqueSectionParser> techniqueSectionParsers() {
  static const TechniqueSectionParser kParsers[] = {
      {underwater::WaterSection::kKey, &underwater::WaterSection::parse},
      {atmosphere::AtmosphereSection::kKey, &atmosphere::AtmosphereSection::parse},
  };
  return kParsers;
}

}  // namespace prism
