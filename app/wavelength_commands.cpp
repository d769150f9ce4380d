#include "app/wavelength_commands.h"

#include <fmt/format.h>

#include <nlohmann/json.hpp>

#include "harness/upsampling_table.h"
#include "harness/wavelength_report.h"
#include "scene/scene_loader.h"

namespace prism::app {
namespace {

nlohmann::json toJson(const FitError& e) { return {{"mean", e.mean}, {"max", e.max}}; }

}  // namespace

void runWavelengthsOptimise(const WavelengthsOptimiseOptions& options) {
  const Scene scene = loadScene(options.scene, options.sets);
  const render::FrameSettings settings = frameSettings(options.settings);
  const harness::WavelengthReport report =
      harness::wavelengthReport(scene, settings, harness::upsamplingTable(scene));
  const FittedWavelengths& set = report.set;
  if (options.json) {
    nlohmann::json weights = nlohmann::json::array();
    for (int c = 0; c < 3; ++c) {
      std::vector<double> row;
      for (Eigen::Index i = 0; i < set.weights.cols(); ++i) row.push_back(set.weights(c, i));
      weights.push_back(row);
    }
    nlohmann::json lights = nlohmann::json::array();
    for (const harness::LightErrors& l : report.lights) {
      nlohmann::json strategies = nlohmann::json::object();
      for (const harness::StrategyErrors& s : l.strategies)
        strategies[s.strategy] = {{"colour_checker", toJson(s.chart)}, {"training_set", toJson(s.training)}};
      lights.push_back({{"light", l.light}, {"delta_e2000", strategies}});
    }
    fmt::print("{}\n", nlohmann::json{{"scene", options.scene.string()},
                                      {"wavelengths_nm", set.lambdaNm},
                                      {"weights_nm", weights},
                                      {"observer", settings.observer},
                                      {"training_reflectances", report.reflectances},
                                      {"cache", report.cacheFile.string()},
                                      {"lights", lights}}
                           .dump(2));
    return;
  }
  fmt::print("{}: {} wavelengths fitted for its lights ({}; cached in {})\n", options.scene.string(),
             set.lambdaNm.size(), settings.observer, report.cacheFile.string());
  fmt::print("  λ (nm):");
  for (double lambda : set.lambdaNm) fmt::print(" {:.0f}", lambda);
  fmt::print("\n");
  const char* rows = "XYZ";
  for (int c = 0; c < 3; ++c) {
    fmt::print("  {} weights (nm):", rows[c]);
    for (Eigen::Index i = 0; i < set.weights.cols(); ++i) fmt::print(" {:.3g}", set.weights(c, i));
    fmt::print("\n");
  }
  fmt::print("One frame against the 1 nm integral under each light alone, ΔE00 mean / max: the ColorChecker; "
             "the {} training reflectances\n",
             report.reflectances);
  for (const harness::LightErrors& l : report.lights) {
    fmt::print("  {}\n", l.light);
    for (const harness::StrategyErrors& s : l.strategies)
      fmt::print("    {:<36} {:7.3f} / {:7.3f}   {:7.3f} / {:7.3f}\n", s.strategy, s.chart.mean, s.chart.max,
                 s.training.mean, s.training.max);
  }
}

}  // namespace prism::app
