// The scene's techniques' precomputation (precomputeTechniques, techniques/technique_pass.h: PRT's
// transfer bake) done ahead of a renderer with a progress bar per piece of work: the passes would
// otherwise do it on their first frame, below harness/, with percentages at most.
#pragma once

#include "scene/scene.h"

namespace prism::harness {

void precomputeTechniques(const Scene& scene);

}  // namespace prism::harness
