#include "techniques/technique_pass.h"

#include "technique_passes.h"

namespace prism {

std::unique_ptr<TechniquePass> makeTechniquePass(std::string_view key) { return makeRegisteredTechniquePass(key); }

void precomputeTechniques(const Scene& scene, const TechniqueProgress& progress) {
  precomputeRegisteredTechniques(scene, progress);
}

void requireTechniquesFit(const Scene& scene) { requireFitsOfRegisteredTechniques(scene); }

}  // namespace prism
