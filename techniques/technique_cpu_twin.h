// The CPU side of a technique's part in the lighting pass. render/cpu_shading.h compiles
// shaders/shared/pixel_shading.glsl as C++ once per combination of techniques, in a class that
// derives from each technique's twin: a class of the technique's own (techniques/<name>/
// <name>_cpu_twin.h) that defines, over the same bytes, the accessors its
// shaders/common_<name>_lighting.glsl defines on the GPU. The twins are listed, with their
// shader defines, in techniques/CMakeLists.txt (PRISM_CPU_TWINS), one line per technique.
#pragma once

#include <functional>
#include <map>
#include <memory>
#include <string>

#include "techniques/technique_section.h"

namespace prism {

// What a technique's GPU passes hold for the lighting pass beyond its block (the sky's tables),
// read back for its CPU twin; each technique derives its own (AtmosphereTexels).
struct TechniqueTexels {
  virtual ~TechniqueTexels() = default;
};

// Texels by technique key.
using TechniqueTexelsByKey = std::map<std::string, std::shared_ptr<const TechniqueTexels>, std::less<>>;

// What a twin is made from: the technique's block of the frame, its texels (null when its
// passes keep none) and the frame's batch count.
struct TechniqueTwinInput {
  const TechniqueBlock& block;
  const TechniqueTexels* texels = nullptr;
  int batchCount = 0;
};

}  // namespace prism
