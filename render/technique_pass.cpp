#include "render/technique_pass.h"

#include "render/atmosphere_pass.h"
#include "techniques/atmosphere/atmosphere_section.h"

namespace prism::render {

std::unique_ptr<TechniquePass> makeTechniquePass(std::string_view key) {
  if (key == atmosphere::AtmosphereSection::kKey) return std::make_unique<AtmospherePass>();
  return nullptr;
}

}  // namespace prism::render
