// shaders/shared/frame_layout.glsl compiled as C++ (inside prism::shared), once per translation
// unit: the lighting pass's buffer layouts, which the renderer fills and the techniques pack
// their blocks against (render/shared_shading.h checks the sizes and offsets).
#pragma once

#include "shared_cpp.h"

namespace prism::shared {
#include "frame_layout.glsl"
}  // namespace prism::shared
