// The post pass's colour maths that is per frame rather than per pixel: one 3×3 from the
// lighting pass's tristimulus to linear display RGB, folding in exposure, the camera matrix (for
// a camera observer), white balance and the display's primaries. It needs only DisplaySettings
// and the observer whose tristimulus it shows; the names in them are resolved once per change
// (DisplayInputs), so an exposure change costs no look-up.
#pragma once

#include <optional>

#include <Eigen/Core>
#include <glm/glm.hpp>

#include "render/frame_settings.h"
#include "spectral/colour_space.h"
#include "spectral/observer.h"

namespace prism::render {

// DisplaySettings' names resolved: the display's colour space, the white balance's white and the
// camera matrix.
struct DisplayInputs {
  const RgbColourSpace* colourSpace = nullptr;
  // The illuminant's white in the shown tristimulus' terms (CIE 1964's for that observer, XYZ for
  // CIE 1931 and cameras; Y = 1); none: no balance.
  std::optional<Eigen::Vector3d> whiteBalanceXyz;
  Eigen::Matrix3d tristimulusToXyz = Eigen::Matrix3d::Identity();  // a camera's fitted matrix, or identity
  // How well the chart pins that matrix down (CameraMatrixFit::chartConditioning); none for the eye.
  std::optional<double> cameraChartConditioning;
};

// A camera's raw RGB → CIE 1931 XYZ for images lit by `light` (D65 when null): its ColorChecker
// fit under the light, scaled to keep the luminance Prism's camera RGB carries (DisplayInputs'
// tristimulusToXyz for a camera; what its EXRs record, imaging::ExrCamera). PRISM_CHECKs isCamera.
Eigen::Matrix3d cameraToXyz(const Observer& camera, const Spectrum* light);

// `tristimulusObserver` is whose tristimulus is shown: XYZ (a CIE observer), or a camera's raw RGB,
// which goes through its matrix fitted on the ColorChecker under `cameraLight` — the scene's light
// (sceneEmission), D65 when none is given or it is dark. A matrix fitted under D65 turned a blue
// LED's camera response into negative luminance: the image came out black. Error on unknown names.
DisplayInputs resolveDisplay(const DisplaySettings& settings, const Observer& tristimulusObserver,
                             const Spectrum* cameraLight = nullptr);

struct DisplayTransform {
  glm::mat3 toDisplay{1.0f};        // tristimulus → linear display RGB, exposure included
  glm::mat3 displayToXyz{1.0f};      // the display's primaries: linear RGB → XYZ (white Y = 1)
  glm::mat3 xyzToDisplay{1.0f};      // and back (no exposure, no white balance)
  int transfer = 0;                  // 0 sRGB curve (sRGB, Display P3), 1 BT.2020
  glm::mat3 toXyz{1.0f};             // tristimulus → XYZ alone (the camera matrix, or identity)
};

DisplayTransform displayTransform(const DisplaySettings& settings, const DisplayInputs& inputs, float sceneEv100);

// The luminance (cd/m²) an exposure of ev100 maps to display white: 1.2 · 2^ev100 (Lagarde &
// de Rousiers 2014), the inverse of shaders/shared/post.glsl's exposureScale.
double displayWhiteLuminance(float ev100);

// The post pass on the CPU for one pixel (shaders/passes/post.frag without the dither): tristimulus
// → display RGB → gamut compression → tone map → hue kept → transfer, clamped to [0, 1]. NaN or ∞
// give black.
glm::vec3 encodeForDisplay(const DisplayTransform& transform, ToneMap toneMap,
                           const glm::vec3& tristimulus);

}  // namespace prism::render
