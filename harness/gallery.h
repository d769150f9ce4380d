// `prism demo`, Prism's main job: every example scene (scenes/*.json) rendered headlessly in RGB
// and in spectral (Jakob–Hanika) mode, side by side, with the CIEDE2000 difference between the
// two, plus the ColorChecker chart; written to a folder with an index.html to look at them. The
// spectral images accumulate rotated wavelength grids over several frames, so that spiky lamps
// (F11, narrow LEDs) converge instead of showing the bias of a few fixed wavelengths.
#pragma once

#include <filesystem>
#include <string>

namespace prism::harness {

struct GalleryOptions {
  std::filesystem::path output = "out/gallery";
  std::filesystem::path scenes;  // default: the example scenes (scenes/ or the installed copy)
  int width = 640;
  int height = 360;
  int wavelengths = 16;  // per frame
  int frames = 32;       // accumulated for the spectral images (rotated grids)
  std::string adaptation = "bradford";  // of the ColorChecker chart
};
void runGallery(const GalleryOptions& options);

}  // namespace prism::harness
