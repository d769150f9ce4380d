// `prism demo`, Prism's main job: every example scene (scenes/*.json) rendered headlessly in RGB
// and in spectral (Jakob–Hanika) mode, side by side, with the CIEDE2000 difference between the
// two, the example nebulae (scenes/nebula/*.json) in the Hubble palette and in natural colour, each
// against its reference, plus the ColorChecker chart; written to a folder with an index.html to look at them and a
// contact sheet of them all (contact_sheet.png, harness/contact_sheet.h). The
// spectral images are one frame of the renderer's default wavelengths, the set fitted for the
// scene's lights, which shows spiky lamps (F11, narrow LEDs) as 200 uniform wavelengths do.
#pragma once

#include <filesystem>
#include <string>

namespace prism::harness {

struct GalleryOptions {
  std::filesystem::path output = "out/gallery";
  std::filesystem::path scenes;  // default: the example scenes (scenes/ or the installed copy)
  int width = 640;
  int height = 360;
  int wavelengths = 16;  // of the spectral images
  std::string adaptation = "bradford";  // of the ColorChecker chart
};
void runGallery(const GalleryOptions& options);

}  // namespace prism::harness
