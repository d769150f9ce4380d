// The nebulae of `prism validate` (issue 15): the example nebulae, in the Hubble palette and in
// natural colour, rendered by the GPU marcher's methods against the CPU's reference (the paper's
// double integration over wavelength: 16 Simpson intervals a passband piece, within 1e-7 of 32),
// in CIEDE2000 as the screen shows them before its clip (nebula_display.h): natural colour as XYZ
// relative to Y's white level, the palette as linear sRGB after each channel's stretch, both
// images by the reference's levels. The GPU's own errors against its CPU twin are rounding
// (nebula_gpu_test); these are each method's against the ground truth.
#pragma once

#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include "imaging/image_difference.h"
#include "techniques/nebula/nebula_render.h"

namespace prism::harness {

struct NebulaExperiment {
  const char* name;    // of the results and images
  const char* scene;   // in the scene directory, without .json
  const char* filters; // hubble or cie1931
};
inline constexpr NebulaExperiment kNebulaExperiments[] = {
    {"nebula_hubble", "nebula/nebula", "hubble"},
    {"nebula_natural", "nebula/nebula", "cie1931"},
    {"ionised_hubble", "nebula/ionised", "hubble"},
    {"ionised_natural", "nebula/ionised", "cie1931"},
};
// The paper's two, its closed form per step (analytic) and its rejected alternative.
inline constexpr nebula::Method kNebulaMethods[] = {nebula::Method::Projection, nebula::Method::LightDensity,
                                                    nebula::Method::Analytic, nebula::Method::PreIntegration};

struct NebulaMethodDifference {
  std::string mode;                 // the method's name
  imaging::ImageDifference difference;  // with its ΔE00 map
};

// Renders `experiment` with its camera scaled to at most `size` pixels a side: the reference on
// the CPU, then each method on the GPU (a current context). Writes OUTPUT/NAME_reference.png and
// OUTPUT/NAME_MODE.png; calls `step` after the reference and after each method.
std::vector<NebulaMethodDifference> runNebulaExperiment(const NebulaExperiment& experiment,
                                                        const std::filesystem::path& sceneDir, int size,
                                                        const std::filesystem::path& output,
                                                        const std::function<void()>& step);

}  // namespace prism::harness
