// The techniques Prism knows, in the order their sections are read: each registered by the
// prism_technique() call in its own CMakeLists.txt (cmake/PrismTechniques.cmake), from which
// the list is generated. The scene loader reads each technique's section through it.
#pragma once

#include <span>

#include "techniques/technique_section.h"

namespace prism {

std::span<const TechniqueSectionParser> techniqueSectionParsers();

// The optimised4 mode's wavelengths for a scene with these sections: the first technique's own
// (TechniqueSection::optimisedWavelengths). Error when none has them: the sky's set, which the
// mode took then, showed a scene of LEDs 10.8 mean ΔE00 from the reference mode.
TechniqueWavelengths optimisedWavelengths(const TechniqueSections& sections);

}  // namespace prism
