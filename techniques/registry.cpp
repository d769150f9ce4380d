#include "techniques/registry.h"

#include "core/error.h"
#include "technique_sections.h"

namespace prism {

std::span<const TechniqueSectionParser> techniqueSectionParsers() {
  return kTechniqueSectionParsers;
}

TechniqueWavelengths optimisedWavelengths(const TechniqueSections& sections) {
  for (const auto& section : sections.all()) {
    if (std::optional<TechniqueWavelengths> own = section->optimisedWavelengths()) return *own;
  }
  throw Error("mode optimised4 renders the four wavelengths fitted for the scene's sky, and it has no atmosphere "
              "section: use jakob-hanika, whose default fits 16 for the scene's lights (--wavelengths 4 for four)");
}

}  // namespace prism
