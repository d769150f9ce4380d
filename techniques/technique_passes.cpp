#include "techniques/technique_pass.h"

#include "techniques/atmosphere/gpu/atmosphere_pass.h"
#include "techniques/atmosphere/atmosphere_section.h"

namespace prism {

std::unique_ptr<TechniquePass> makeTechniquePass(std::string_view key) {
  if (key == atmosphere::AtmosphereSection::kKey) return std::make_unique<atmosphere::AtmospherePass>();
  return nullptr;
}

}  // namespace prism
