#include "techniques/atmosphere/sky_strategy.h"

#include <cmath>
#include <map>
#include <mutex>
#include <string>
#include <vector>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "spectral/colour_space.h"
#include "core/data_files.h"
#include "core/error.h"
#include "core/json_schema.h"
#include "spectral/observer.h"
#include "spectral/sampling.h"
#include "techniques/atmosphere/atmosphere_parameters.h"

namespace prism::atmosphere {
namespace {

// Wavelengths with integration weights (nm) into batches of four.
SkyStrategy weighted(std::string name, const std::vector<double>& lambdas, const std::vector<double>& weights) {
  const Observer& cie = observer("cie1931");
  const double scale = absoluteTristimulusScale(cie);  // 683 lm/W
  SkyStrategy s{std::move(name), {}};
  for (std::size_t i = 0; i < lambdas.size(); i += 4) {
    SkyBatch b;
    for (std::size_t j = 0; j < 4 && i + j < lambdas.size(); ++j) {
      double lambda = lambdas[i + j];
      b.lambdaNm[static_cast<int>(j)] = static_cast<float>(lambda);
      b.solarIrradiance[static_cast<int>(j)] = static_cast<float>(solarIrradiance(lambda));
      b.toXyz.col(static_cast<Eigen::Index>(j)) = cie.at(lambda) * weights[i + j] * scale;
    }
    s.batches.push_back(b);
  }
  return s;
}

}  // namespace

SkyStrategy referenceStrategy(double stepNm) {
  if (!(stepNm >= 0.5 && stepNm <= 50.0)) throw Error(fmt::format("reference step {} nm must be within 0.5..50", stepNm));
  int n = static_cast<int>(std::lround((kLambdaMaxNm - kLambdaMinNm) / stepNm));
  std::vector<double> lambdas, weights;
  double h = double(kLambdaMaxNm - kLambdaMinNm) / n;
  for (int i = 0; i <= n; ++i) {
    lambdas.push_back(kLambdaMinNm + h * i);
    weights.push_back(i == 0 || i == n ? 0.5 * h : h);
  }
  return weighted(fmt::format("reference {:g} nm", h), lambdas, weights);
}

SkyStrategy uniformStrategy(int count) {
  validateWavelengthCount(count);
  std::vector<double> lambdas, weights;
  double h = double(kLambdaMaxNm - kLambdaMinNm) / count;
  for (int i = 0; i < count; ++i) {
    lambdas.push_back(kLambdaMinNm + h * (i + 0.5));
    weights.push_back(h);
  }
  return weighted(fmt::format("uniform {}", count), lambdas, weights);
}

SkyStrategy rgbStrategy() {
  const RgbColourSpace& srgb = colourSpace("srgb");
  const Observer& cie = observer("cie1931");
  Eigen::Vector3d sunXyz = absoluteTristimulusScale(cie) * cie.integrate(solarIrradianceSpectrum().toDense());
  Eigen::Vector3d sunRgb = srgb.xyzToRgb * sunXyz;
  SkyBatch b;
  b.lambdaNm = glm::vec4(kRgbStandInWavelengthsNm[0], kRgbStandInWavelengthsNm[1], kRgbStandInWavelengthsNm[2], 0.0f);
  b.solarIrradiance = glm::vec4(sunRgb.x(), sunRgb.y(), sunRgb.z(), 0.0f);
  b.toXyz.leftCols<3>() = srgb.rgbToXyz;
  return SkyStrategy{"rgb 680/550/440", {b}};
}

SkyStrategy optimisedStrategy(const OptimisedWavelengths& set, bool twelve) {
  std::vector<double> lambdas(set.lambdaNm.begin(), set.lambdaNm.end());
  std::vector<double> weights(set.weights.begin(), set.weights.end());
  SkyStrategy s = weighted("optimised 4 (8 parameters)", lambdas, weights);
  if (twelve) {
    if (!set.hasMatrix) throw Error("the optimised wavelength set has no fitted 3x4 matrix");
    s.name = "optimised 4 (12 parameters)";
    s.batches[0].toXyz = set.matrix * absoluteTristimulusScale(observer("cie1931"));
  }
  return s;
}

OptimisedWavelengths loadOptimisedWavelengths(const std::filesystem::path& file, std::string_view set) {
  const std::vector<unsigned char> bytes = schema::readBinaryFile(file);
  const nlohmann::json j =
      schema::parseJson(std::string_view(reinterpret_cast<const char*>(bytes.data()), bytes.size()), file.string());
  const schema::Document document{file.string(), {}};
  const schema::Node root(j, "", document);
  // What `prism atmosphere optimise` writes: a misspelt key is refused, not ignored.
  root.expectObject({"sets", "settings"});
  const schema::Node sets = root.child("sets");
  sets.expectObject({"aerosols", "rayleigh-ozone"});
  if (!sets.has(set)) sets.fail(fmt::format("missing required key '{}' (the wavelength set of that atmosphere)", set));
  const schema::Node s = sets.child(set);
  s.expectObject({"lambda_nm", "weights_nm", "matrix", "objective_grid", "objective_8", "objective_12", "evaluations"});
  OptimisedWavelengths w;
  const schema::Node lambda = s.child("lambda_nm");
  const schema::Node weights = s.child("weights_nm");
  const std::vector<double> lambdaNm = lambda.numbers(4, schema::Range::closed(kLambdaMinNm, kLambdaMaxNm));
  const std::vector<double> weightsNm = weights.numbers(4, schema::Range::above(0.0).forFloat());
  for (std::size_t i = 0; i < 4; ++i) {
    if (i > 0 && !(lambdaNm[i] > lambdaNm[i - 1]))
      lambda.element(i).fail(fmt::format("{:g} nm does not follow {:g} nm (four increasing wavelengths)", lambdaNm[i],
                                         lambdaNm[i - 1]));
    w.lambdaNm[i] = lambdaNm[i];
    w.weights[i] = weightsNm[i];
  }
  // The 12-parameter strategy's matrix, fitted with the weights: a set without it is incomplete,
  // and a row of zeros would leave X, Y or Z at 0 whatever the sky.
  const schema::Node matrix = s.child("matrix");
  if (!matrix.json().is_array() || matrix.arraySize() != 3)
    matrix.fail("expected 3 rows of 4 numbers, got " + schema::describe(matrix.json()));
  for (std::size_t r = 0; r < 3; ++r) {
    const std::vector<double> row = matrix.element(r).numbers(4, schema::Range::any().forFloat());
    if (row[0] == 0.0 && row[1] == 0.0 && row[2] == 0.0 && row[3] == 0.0)
      matrix.element(r).fail(fmt::format("a row of zeros gives every sky {} = 0", "XYZ"[r]));
    for (std::size_t c = 0; c < 4; ++c) w.matrix(static_cast<int>(r), static_cast<int>(c)) = row[c];
  }
  w.hasMatrix = true;
  return w;
}

OptimisedWavelengths loadOptimisedWavelengths(std::string_view set) {
  // Read once per set: the renderer asks every frame.
  static std::mutex mutex;
  static std::map<std::string, OptimisedWavelengths, std::less<>> cache;
  std::lock_guard lock(mutex);
  auto it = cache.find(set);
  if (it == cache.end()) {
    it = cache.emplace(std::string(set), loadOptimisedWavelengths(dataFile("atmosphere_wavelengths.json"), set)).first;
  }
  return it->second;
}

}  // namespace prism::atmosphere
