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
  if (count < 4 || count % 4 != 0 || count > 1000) {
    throw Error(fmt::format("uniform wavelength count {} must be a multiple of 4 within 4..1000", count));
  }
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
  // The value at /sets/SET/KEY: an array of `count` numbers (each of `rows` if rows > 0).
  const std::string at = fmt::format("/sets/{}", schema::pointerToken(set));
  const nlohmann::json* s = j.is_object() && j.contains("sets") && j["sets"].is_object() && j["sets"].contains(std::string(set))
                                ? &j["sets"][std::string(set)]
                                : nullptr;
  if (s == nullptr || !s->is_object()) throw Error(fmt::format("{}: {}: missing (the wavelength set of that atmosphere)", file.string(), at));
  // Within ±kFloatInputLimit, as every number Prism reads: 1e300 in the matrix printed NaN errors.
  auto numbers = [&](const nlohmann::json& v, const std::string& where, std::size_t count) {
    std::vector<double> out;
    if (v.is_array() && v.size() == count)
      for (const nlohmann::json& x : v)
        if (x.is_number()) out.push_back(x.get<double>());
    if (out.size() != count)
      throw Error(fmt::format("{}: {}: expected an array of {} numbers, got {}", file.string(), where, count, schema::describe(v)));
    for (std::size_t i = 0; i < count; ++i)
      if (!(std::abs(out[i]) <= schema::kFloatInputLimit))
        throw Error(fmt::format("{}: {}/{}: {:g} is outside ±{:g}", file.string(), where, i, out[i], schema::kFloatInputLimit));
    return out;
  };
  auto member = [&](const char* key) -> const nlohmann::json& {
    if (!s->contains(key)) throw Error(fmt::format("{}: {}/{}: missing", file.string(), at, key));
    return (*s)[key];
  };
  OptimisedWavelengths w;
  const std::vector<double> lambda = numbers(member("lambda_nm"), at + "/lambda_nm", 4);
  const std::vector<double> weights = numbers(member("weights_nm"), at + "/weights_nm", 4);
  for (std::size_t i = 0; i < 4; ++i) {
    if (!(lambda[i] >= kLambdaMinNm && lambda[i] <= kLambdaMaxNm))
      throw Error(fmt::format("{}: {}/lambda_nm/{}: {:g} nm is outside 360..830 nm", file.string(), at, i, lambda[i]));
    if (i > 0 && !(lambda[i] > lambda[i - 1]))
      throw Error(fmt::format("{}: {}/lambda_nm/{}: {:g} nm does not follow {:g} nm (four increasing wavelengths)",
                              file.string(), at, i, lambda[i], lambda[i - 1]));
    if (!(weights[i] > 0.0))
      throw Error(fmt::format("{}: {}/weights_nm/{}: {:g} nm is not positive (a quadrature weight)", file.string(), at, i,
                              weights[i]));
    w.lambdaNm[i] = lambda[i];
    w.weights[i] = weights[i];
  }
  // The 12-parameter strategy's matrix, fitted with the weights: a set without it is incomplete.
  const nlohmann::json& m = member("matrix");
  if (!m.is_array() || m.size() != 3)
    throw Error(fmt::format("{}: {}/matrix: expected 3 rows of 4 numbers, got {}", file.string(), at, schema::describe(m)));
  for (std::size_t r = 0; r < 3; ++r) {
    const std::vector<double> row = numbers(m[r], fmt::format("{}/matrix/{}", at, r), 4);
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
