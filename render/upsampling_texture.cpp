#include "render/upsampling_texture.h"

namespace prism::render {

gpu::Texture3D uploadUpsamplingTable(const RgbToSpectrumTable& table) {
  const int res = table.resolution();
  return gpu::Texture3D({res, res, 3 * res, GL_RGB32F, GL_RGB, table.data(),
                         "upsampling table " + table.gamut()});
}

}  // namespace prism::render
