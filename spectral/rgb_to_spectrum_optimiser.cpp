#include "spectral/rgb_to_spectrum_optimiser.h"

#include <string>

#include "spectral/colour_space.h"
#include "spectral/observer.h"
#include "core/error.h"
#include "core/parallel_for.h"
#include "spectral/sigmoid_fit.h"

namespace prism {

int tableColumns(int resolution) { return 3 * resolution * resolution; }

void requireBuildableResolution(int resolution) {
  if (resolution < kMinBuiltTableResolution || resolution > kMaxBuiltTableResolution) {
    throw Error("upsampling table resolution must be within " + std::to_string(kMinBuiltTableResolution) + "–" +
                std::to_string(kMaxBuiltTableResolution) + ", got " + std::to_string(resolution));
  }
}

RgbToSpectrumTable buildRgbToSpectrumTable(const TableBuildOptions& options) {
  return buildRgbToSpectrumTable(options, {0, tableColumns(options.resolution)});
}

RgbToSpectrumTable buildRgbToSpectrumTable(const TableBuildOptions& options, IndexRange columns) {
  requireBuildableResolution(options.resolution);
  const RgbColourSpace& gamut = colourSpace(options.gamut);
  RgbToSpectrumTable table(options.gamut, options.resolution);
  const SigmoidFitter fitter(gamut, gamutWhiteIlluminant(gamut), observer("cie1931"));
  const int res = options.resolution;
  PRISM_CHECK(columns.begin >= 0 && columns.begin < columns.end && columns.end <= tableColumns(res));

  auto solveColumn = [&](std::size_t item) {
    const std::size_t column = static_cast<std::size_t>(columns.begin) + item;
    int block = static_cast<int>(column / static_cast<std::size_t>(res * res));
    int yi = static_cast<int>(column / static_cast<std::size_t>(res)) % res;
    int xi = static_cast<int>(column % static_cast<std::size_t>(res));
    auto fitNode = [&](int zi, const Eigen::Vector3d& seed) {
      glm::vec3 rgb = table.nodeRgb(block, zi, yi, xi);
      SigmoidFit fit = fitter.fit(Eigen::Vector3d(rgb.x, rgb.y, rgb.z), seed);
      table.setCoefficients(block, zi, yi, xi, fit.coeffs);
      return fit.normalised;
    };
    const int start = res / 5;
    Eigen::Vector3d startSolution = fitNode(start, Eigen::Vector3d::Zero());
    Eigen::Vector3d seed = startSolution;
    for (int zi = start + 1; zi < res; ++zi) seed = fitNode(zi, seed);
    seed = startSolution;
    for (int zi = start - 1; zi >= 0; --zi) seed = fitNode(zi, seed);
  };

  parallelFor(static_cast<std::size_t>(columns.size()), options.threads, solveColumn, options.progress);
  return table;
}

}  // namespace prism
