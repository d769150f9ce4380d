// The path tracer's view of glTF's emission (scene/scene.h's Material::emissiveFactor): the
// colour a light's, upsampled as the rasteriser's lighting pass does (render_test's
// EmittingMaterials holds that side).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "reference/path_tracer.h"
#include "scene/procedural_mesh.h"
#include "spectral/colour_space.h"
#include "spectral/observer.h"
#include "spectral/rgb_intent.h"
#include "spectral/rgb_to_spectrum_cache.h"

namespace prism::reference {
namespace {

// glTF's emission under direct transport, in the dark: every pixel of the sphere is its colour
// upsampled as a light's (RgbIlluminantSpectrum, the rasteriser's), factor × the texture's one
// texel (sRGB, decoded) at the material's luminance.
TEST(PathTracer, GltfEmissionIsItsColourAsALight) {
  Scene scene;
  scene.camera.position = {0.0f, 0.0f, 3.0f};
  scene.camera.target = {0.0f, 0.0f, 0.0f};
  Image texel;
  texel.width = texel.height = 1;
  texel.rgba = {255, 128, 0, 255};
  texel.srgb = true;
  scene.textures.push_back(texel);
  scene.meshes.push_back(makeSphere({0.0f, 0.0f, 0.0f}, 1.0f, 64));
  const double decoded = std::pow((128.0 / 255.0 + 0.055) / 1.055, 2.4);  // sRGB's transfer function
  for (const bool textured : {false, true}) {
    Material m;
    m.baseColour = glm::vec3(0.0f);
    m.lambertian = true;
    m.emissiveFactor = textured ? glm::vec3(1.0f, 0.8f, 0.3f) : glm::vec3(0.2f, 0.5f, 1.0f);
    m.emissiveTexture = textured ? 0 : -1;
    m.emissiveLuminance = 80.0f;
    scene.materials = {m};
    const glm::vec3 colour = textured ? m.emissiveFactor * glm::vec3(1.0f, static_cast<float>(decoded), 0.0f)
                                      : m.emissiveFactor;
    const Eigen::Vector3d expected = luminousTristimulus(
        RgbIlluminantSpectrum(rendererRgbToSpectrumTable("srgb"), colourSpace("srgb"), colour, m.emissiveLuminance).toDense());
    ReferenceSettings settings;
    settings.width = 48;
    settings.height = 32;
    settings.samplesPerPixel = 64;
    settings.filter = PixelFilter::Centre;
    ReferenceImage image = renderReference(scene, rendererRgbToSpectrumTable("srgb"), settings);
    Eigen::Vector3d mean = Eigen::Vector3d::Zero();
    int onSphere = 0;
    for (std::size_t i = 0; i < image.tristimulus.pixelCount(); ++i) {
      if (image.tristimulus.pixels[3 * i + 1] <= 0.0f) continue;  // the black background
      for (int c = 0; c < 3; ++c) mean[c] += image.tristimulus.pixels[3 * i + static_cast<std::size_t>(c)];
      ++onSphere;
    }
    mean /= onSphere;
    std::printf("%s: %d pixels, mean XYZ (%.4f, %.4f, %.4f), expected (%.4f, %.4f, %.4f)\n",
                textured ? "textured" : "flat", onSphere, mean.x(), mean.y(), mean.z(), expected.x(), expected.y(),
                expected.z());
    EXPECT_GT(onSphere, 200) << textured;
    // Hero wavelengths over 64 paths a pixel, hundreds of pixels: as the white furnace's mean.
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(mean[c] / expected[c], 1.0, 3e-3) << textured << " channel " << c;
  }
}

}  // namespace
}  // namespace prism::reference
