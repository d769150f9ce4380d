// Wavelength strategies for the sky, all rendered by the same code (one batch of four
// wavelengths at a time) and turned into absolute XYZ (Y in cd/m²) by a 3×4 matrix per batch:
//   reference   every `stepNm` from 360 to 830 nm (trapezoid weights), batches of four;
//   rgb         680, 550, 440 nm used directly as R, G, B (the common practice): the sun's
//               irradiance at those channels is replaced by the sun's own linear sRGB, so the
//               top-of-atmosphere sun comes out exactly right, and sRGB → XYZ integrates;
//   uniform n   the midpoints of n equal bins (n a multiple of 4);
//   optimised   García Liñán's four wavelengths λ₁..λ₄ with weights w: M[c][i] = c̄(λᵢ)·wᵢ
//               (8 parameters), or the full fitted 3×4 matrix M (12 parameters), read from
//               data/atmosphere_wavelengths.json (`prism atmosphere optimise` writes it).
#pragma once

#include <array>
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include <Eigen/Core>
#include <glm/glm.hpp>

namespace prism::atmosphere {

struct SkyBatch {
  glm::vec4 lambdaNm{0.0f};         // ≤ 0: an unused channel
  glm::vec4 solarIrradiance{0.0f};  // what the batch takes as the sun, per channel
  Eigen::Matrix<double, 3, 4> toXyz = Eigen::Matrix<double, 3, 4>::Zero();  // absolute (×683)
};

struct SkyStrategy {
  std::string name;
  std::vector<SkyBatch> batches;
};

// The four wavelengths and their integration, as optimised.
struct OptimisedWavelengths {
  std::array<double, 4> lambdaNm{};
  std::array<double, 4> weights{};  // nm: M[c][i] = c̄(λᵢ)·wᵢ
  Eigen::Matrix<double, 3, 4> matrix = Eigen::Matrix<double, 3, 4>::Zero();  // the 12-parameter fit
  bool hasMatrix = false;
};

SkyStrategy referenceStrategy(double stepNm);
SkyStrategy rgbStrategy();
SkyStrategy uniformStrategy(int count);
// twelve: the fitted matrix (requires hasMatrix) instead of c̄(λᵢ)·wᵢ.
SkyStrategy optimisedStrategy(const OptimisedWavelengths& set, bool twelve);

// The sets in data/atmosphere_wavelengths.json (read once per set and process): "aerosols" or
// "rayleigh-ozone". Error naming the file and the key when it is missing, malformed or unknown
// (what `prism atmosphere optimise` writes, and nothing else).
OptimisedWavelengths loadOptimisedWavelengths(std::string_view set);
OptimisedWavelengths loadOptimisedWavelengths(const std::filesystem::path& file, std::string_view set);

}  // namespace prism::atmosphere
