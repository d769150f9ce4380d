// A nebula scene file: a JSON document whose "nebula" section describes the model
// (nebula_render.h) — density (noise or a prism-density file beside the scene), extinction,
// scattering, emission lines, stars, camera, filters, ray steps. Errors name the file and the
// JSON pointer ("scenes/nebula/nebula.json: /nebula/stars/0/temperature: …").
//
// The section is read here rather than through the technique seam (techniques/registry.h): the
// seam's sections pack a block for the rasteriser's lighting pass, and a nebula is a volume that
// a ray marcher integrates on its own, which that pass has no hook for yet.
#pragma once

#include <filesystem>

#include "techniques/nebula/nebula_render.h"

namespace prism::nebula {

struct NebulaScene {
  NebulaModel model;
  int steps = 100;
};

NebulaScene loadNebulaScene(const std::filesystem::path& path, unsigned threads = 0);

// The benchmarks' nebula (prism bench's nebulaFrame rows, prism nebula bench): a 32³ fBm cloud
// (seed 7), extinction 3, Hubble palette, 64×64 pixels, `stars` stars on a ring around the
// centre from 4000 to 30000 K. Without emission lines.
NebulaModel benchNebulaModel(int stars);

}  // namespace prism::nebula
