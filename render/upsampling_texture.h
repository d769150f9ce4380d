// The upsampling table on the GPU: one GL_RGB32F 3D texture of res × res × 3·res texels (the
// three blocks one after another along z), filtered linearly, which is exactly the table's own
// data order. shaders/common_upsampling.glsl samples it.
#pragma once

#include "gpu/texture.h"
#include "spectral/rgb_to_spectrum_table.h"

namespace prism::render {

gpu::Texture3D uploadUpsamplingTable(const RgbToSpectrumTable& table);

}  // namespace prism::render
