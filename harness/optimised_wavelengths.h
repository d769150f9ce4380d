// The Optimised strategy's fitted set for a scene, fitted ahead of the renderer with a progress bar:
// a renderer builds its sampler in its constructor (render/frame_context.h), silently, and finds
// the set fitted here in the cache (spectral/wavelength_fit.h). Nothing to do for other strategies.
// A set whose mean ΔE00 over its training set passes kVisibleFitError (a range too narrow for its
// lights, too few wavelengths) is warned of on stderr, at every use: the image shows it.
#pragma once

#include "render/frame_settings.h"
#include "scene/scene.h"
#include "spectral/rgb_to_spectrum_table.h"

namespace prism::harness {

inline constexpr double kVisibleFitError = 2.0;  // mean ΔE00: a difference seen at a glance

void fitOptimisedWavelengths(const Scene& scene, const render::FrameSettings& settings,
                             const RgbToSpectrumTable& table);

}  // namespace prism::harness
