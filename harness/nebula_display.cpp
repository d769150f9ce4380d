#include "harness/nebula_display.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <vector>

#include <Eigen/Core>

#include "spectral/colour_space.h"

namespace prism::harness {
namespace {

double whiteLevel(std::vector<double> values) {
  if (values.empty()) return 1.0;
  std::size_t at = std::min(values.size() - 1, static_cast<std::size_t>(0.995 * static_cast<double>(values.size())));
  std::nth_element(values.begin(), values.begin() + static_cast<std::ptrdiff_t>(at), values.end());
  return values[at] > 0.0 ? values[at] : 1.0;
}

}  // namespace

imaging::PngImage nebulaDisplayPng(const nebula::NebulaImage& image, bool hubble) {
  const RgbColourSpace& srgb = colourSpace("srgb");
  std::vector<Eigen::Vector3d> rgb;
  std::array<std::vector<double>, 3> channels;
  for (const auto& p : image.pixels) {
    Eigen::Vector3d v(p.x, p.y, p.z);
    if (!hubble) v = srgb.xyzToRgb * v;
    rgb.push_back(v);
    for (int c = 0; c < 3; ++c) channels[static_cast<std::size_t>(c)].push_back(hubble ? v[c] : p.y);
  }
  Eigen::Vector3d white(whiteLevel(channels[0]), whiteLevel(channels[1]), whiteLevel(channels[2]));
  imaging::PngImage png(image.width, image.height, {0, 0, 0});
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x) {
      Eigen::Vector3d v =
          rgb[static_cast<std::size_t>(y * image.width + x)].cwiseQuotient(white).cwiseMax(0.0).cwiseMin(1.0);
      Eigen::Vector3d e = srgb.encode(v);
      auto q = [](double u) { return static_cast<std::uint8_t>(std::lround(std::clamp(u, 0.0, 1.0) * 255.0)); };
      png.setPixel(x, y, {q(e[0]), q(e[1]), q(e[2])});
    }
  return png;
}

}  // namespace prism::harness
