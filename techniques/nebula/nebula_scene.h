// A nebula scene file: a JSON document whose "nebula" section describes the model
// (nebula_render.h) — density (noise or a prism-density file beside the scene), extinction,
// scattering, emission lines, stars, camera, filters, ray steps. Errors name the file and the
// JSON pointer ("scenes/nebula/nebula.json: /nebula/stars/0/temperature: …").
//
// A scene of the renderer holds a nebula as its "nebula" section (nebula_section.h), which reads
// the same keys but the camera (readNebulaKeys).
#pragma once

#include <cstddef>
#include <filesystem>
#include <functional>
#include <optional>

#include "core/json_schema.h"

#include "techniques/nebula/nebula_render.h"

namespace prism::nebula {

struct NebulaScene {
  NebulaModel model;
  int steps = 100;
};

// The emission-line groups a scene may name ("lines"), as in data/nebula_lines.csv, and the
// stars' temperature range.
inline constexpr const char* kLineGroups[] = {"H I Balmer (case B)", "He I (case B)", "[O III] doublet",
                                              "[N II] doublet", "[S II] doublet", "[O II] doublet", "[O I] doublet"};
inline constexpr double kMinStarTemperatureK = 1000.0, kMaxStarTemperatureK = 100000.0;

// Where a model's density came from: noise (which an editor may change and generate again) or a
// density file (resolved beside the scene file).
struct DensitySource {
  std::optional<NoiseParameters> noise;
  std::filesystem::path file;
};

// Reads the keys a nebula scene file and a scene's "nebula" section share — density, extinction,
// scattering, scattering_spectrum, emission, lines, ionisation, stars, star_model, filters, passbands, steps — into `m`
// and `steps`; the caller says which keys the node may have (schema::Node::expectObject). A
// density file is read into m.density; noise is left to the caller to generate (the source's).
DensitySource readNebulaKeys(const schema::Node& n, NebulaModel& m, int& steps);

// A nebula scene file's keys, its noise not generated yet (model.density is empty when
// source.noise is set): what a command checks before the work.
struct NebulaSceneFile {
  NebulaScene scene;
  DensitySource source;
  // The density's NX, NY, NZ, generated or not.
  glm::ivec3 densitySize() const;
};
NebulaSceneFile readNebulaScene(const std::filesystem::path& path);

// The scene with its noise generated with `threads` (0: all), reporting to `progress`.
using DensityProgress = std::function<void(std::size_t done, std::size_t total)>;
NebulaScene generateDensity(NebulaSceneFile file, unsigned threads = 0, const DensityProgress& progress = {});

// Both.
NebulaScene loadNebulaScene(const std::filesystem::path& path, unsigned threads = 0);

// The benchmarks' nebula (prism bench's nebulaFrame rows, prism nebula bench): a 32³ fBm cloud
// (seed 7), extinction 3, Hubble palette, 64×64 pixels, `stars` stars on a ring around the
// centre from 4000 to 30000 K. Without emission lines.
NebulaModel benchNebulaModel(int stars);

}  // namespace prism::nebula
