#include "spectral/rgb_to_spectrum_optimiser.h"

#include "spectral/colour_space.h"
#include "spectral/observer.h"
#include "core/parallel_for.h"
#include "spectral/sigmoid_fit.h"

namespace prism {

RgbToSpectrumTable buildRgbToSpectrumTable(const TableBuildOptions& options) {
  const RgbColourSpace& gamut = colourSpace(options.gamut);
  RgbToSpectrumTable table(options.gamut, options.resolution);
  const SigmoidFitter fitter(gamut, gamutWhiteIlluminant(gamut), observer("cie1931"));
  const int res = options.resolution;
  const std::size_t columns = 3 * static_cast<std::size_t>(res) * static_cast<std::size_t>(res);

  auto solveColumn = [&](std::size_t column) {
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

  parallelFor(columns, options.threads, solveColumn, options.progress);
  return table;
}

}  // namespace prism
