// The Optimised strategy's fitted set for a scene, fitted ahead of the renderer with a progress bar:
// a renderer builds its sampler in its constructor (render/frame_context.h), silently, and finds
// the set fitted here in the cache (spectral/wavelength_fit.h). Nothing to do for other strategies.
#pragma once

#include "render/frame_settings.h"
#include "scene/scene.h"
#include "spectral/rgb_to_spectrum_table.h"

namespace prism::harness {

void fitOptimisedWavelengths(const Scene& scene, const render::FrameSettings& settings,
                             const RgbToSpectrumTable& table);

}  // namespace prism::harness
