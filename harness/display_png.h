// Display-referred 8-bit images of what Prism renders, as PNGs. displayPng: the renderer's
// display target (after its post pass, dither included), opaque. displayImage: linear
// tristimulus (XYZ, or camera RGB when `tristimulusObserver` is a camera) through the post pass's
// maths on the CPU (render::encodeForDisplay, no dither), i.e. what `prism render` would show of
// a reference image.
#pragma once

#include <optional>

#include <Eigen/Core>

#include "imaging/float_image.h"
#include "imaging/png_file.h"
#include "render/frame_settings.h"
#include "spectral/observer.h"
#include "render/renderer.h"

namespace prism::harness {

imaging::PngImage displayPng(const render::Renderer& renderer);

// `cameraToXyz`: a camera's matrix (render::cameraToXyz under the scene's light; its D65 fit
// without one).
imaging::PngImage displayImage(const imaging::FloatImage& tristimulus, const render::DisplaySettings& settings,
                               const Observer& tristimulusObserver, float sceneEv100,
                               const std::optional<Eigen::Matrix3d>& cameraToXyz = std::nullopt);

}  // namespace prism::harness
