// The post pass's colour maths that is per frame rather than per pixel: one 3×3 from the
// lighting pass's tristimulus to linear display RGB, folding in exposure, the camera matrix (for
// a camera observer), white balance and the display's primaries.
#pragma once

#include <glm/glm.hpp>

#include "render/frame_settings.h"

namespace prism::render {

struct DisplayTransform {
  glm::mat3 toDisplay{1.0f};        // tristimulus → linear display RGB, exposure included
  glm::vec3 luminanceWeights{0.0f};  // the display's Y row: luminance of a linear RGB
  int transfer = 0;                  // 0 sRGB curve (sRGB, Display P3), 1 BT.2020
  glm::mat3 toXyz{1.0f};             // tristimulus → XYZ alone (the camera matrix, or identity)
};

DisplayTransform displayTransform(const FrameSettings& settings, float sceneEv100);

// The luminance (cd/m²) an exposure of ev100 maps to display white: 1.2 · 2^ev100 (Lagarde &
// de Rousiers 2014), the inverse of shaders/shared/post.glsl's exposureScale.
double displayWhiteLuminance(float ev100);

// The post pass on the CPU for one pixel (shaders/passes/post.frag without the dither): tristimulus
// → display RGB → gamut compression → tone map → transfer, clamped to [0, 1]. NaN or ∞ give black.
glm::vec3 encodeForDisplay(const DisplayTransform& transform, ToneMap toneMap,
                           const glm::vec3& tristimulus);

}  // namespace prism::render
