// The techniques Prism knows, in the order their sections are read: the one place a new
// technique is registered (one line in registry.cpp). The scene loader reads each technique's
// section through it.
#pragma once

#include <span>

#include "techniques/technique_section.h"

namespace prism {

std::span<const TechniqueSectionParser> techniqueSectionParsers();

}  // namespace prism
