// Loads an installed example scene and renders one small frame headlessly with the installed
// shaders: prints the share of pixels that saw geometry.
#include <cstdio>

#include "gpu/headless_context.h"
#include "render/renderer.h"
#include "scene/scene_loader.h"
#include "spectral/rgb_to_spectrum_optimiser.h"

int main() {
  prism::Scene scene = prism::loadScene(SCENE);
  prism::RgbToSpectrumTable table = prism::buildRgbToSpectrumTable({"srgb", 8, 0, {}});
  prism::gpu::HeadlessContext context;
  prism::render::FrameSettings settings;
  settings.width = 32;
  settings.height = 18;
  settings.shadowMapSize = 64;
  prism::render::Renderer renderer(scene, table, settings);
  renderer.renderFrame();
  std::vector<float> xyz = renderer.readMeanTristimulus();
  int lit = 0;
  for (std::size_t i = 1; i < xyz.size(); i += 3) lit += xyz[i] > 0.0f;
  std::printf("rendered %dx%d, %s\n", settings.width, settings.height,
              lit > 32 * 18 / 2 ? "mostly geometry" : "mostly empty");
  return 0;
}
