#include "render/atmosphere_texels_test_support.h"

namespace prism::render {
namespace {

std::vector<std::vector<glm::vec4>> readLayers(const gpu::Texture2DArray& t) {
  std::vector<std::vector<glm::vec4>> layers;
  for (GLint l = 0; l < t.layers(); ++l) {
    std::vector<float> v = gpu::readTextureLayerFloat(t, l, 4);
    std::vector<glm::vec4> texels(v.size() / 4);
    for (std::size_t i = 0; i < texels.size(); ++i) texels[i] = glm::vec4(v[4 * i], v[4 * i + 1], v[4 * i + 2], v[4 * i + 3]);
    layers.push_back(std::move(texels));
  }
  return layers;
}

}  // namespace

AtmosphereTexels readAtmosphereTexels(const atmosphere::AtmospherePass& pass) {
  AtmosphereTexels a;
  a.transmittance = readLayers(pass.transmittance());
  a.multipleScattering = readLayers(pass.multipleScattering());
  a.skyView = readLayers(pass.skyView());
  a.aerialPerspective = readLayers(pass.aerialPerspective());
  a.skyIrradiance = pass.skyIrradiance().read<glm::vec4>();
  return a;
}

}  // namespace prism::render
