// Loads an installed example scene and traces one small image with the installed reference path
// tracer: prints the share of pixels that saw lit geometry.
#include <cstdio>

#include "reference/path_tracer.h"
#include "scene/scene_loader.h"
#include "spectral/rgb_to_spectrum_optimiser.h"

int main() {
  prism::Scene scene = prism::loadScene(SCENE);
  prism::RgbToSpectrumTable table = prism::buildRgbToSpectrumTable({"srgb", 8, 0, {}});
  prism::reference::ReferenceSettings settings;
  settings.width = 32;
  settings.height = 18;
  settings.samplesPerPixel = 2;
  prism::reference::ReferenceImage image = prism::reference::renderReference(scene, table, settings);
  int lit = 0;
  for (std::size_t i = 1; i < image.tristimulus.pixels.size(); i += 3) lit += image.tristimulus.pixels[i] > 0.0f;
  std::printf("traced %dx%d, %s\n", settings.width, settings.height,
              lit > 32 * 18 / 2 ? "mostly geometry" : "mostly empty");
  return 0;
}
