#include "spectral/observer.h"

#include <map>

#include "core/csv.h"
#include "spectral/spectrum_csv.h"
#include "core/data_files.h"
#include "core/error.h"
#include "core/name_case.h"
#include "shared_cpp.h"
#include "spectral/illuminant.h"

namespace prism {
namespace {

Observer loadCie(const std::string& name, const char* file) {
  SpectraTable table = SpectraTable::read(dataFile(file),
                                          std::vector<std::string_view>{"x_bar", "y_bar", "z_bar"});
  Observer obs{name, false, {}};
  const char* columns[3] = {"x_bar", "y_bar", "z_bar"};
  for (int c = 0; c < 3; ++c)
    obs.curves[static_cast<std::size_t>(c)] = table.spectrum(columns[c], Extrapolation::Zero).toDense();
  return obs;
}

// data/cameras.csv is long format: camera, wavelength_nm, r, g, b, source.
std::map<std::string, Observer, std::less<>> loadCameras() {
  CsvTable csv = CsvTable::read(dataFile("cameras.csv"));
  int nameCol = csv.column("camera");
  int lambdaCol = csv.column("wavelength_nm");
  int rgbCols[3] = {csv.column("r"), csv.column("g"), csv.column("b")};
  struct Columns {
    std::vector<double> lambdas;
    std::vector<int> lines;
    std::array<std::vector<double>, 3> rgb;
  };
  std::map<std::string, Columns, std::less<>> byCamera;
  for (const CsvRow& row : csv.rows()) {
    Columns& c = byCamera[row.fields[static_cast<std::size_t>(nameCol)]];
    c.lambdas.push_back(csv.number(row, lambdaCol));
    c.lines.push_back(row.line);
    for (std::size_t k = 0; k < 3; ++k) c.rgb[k].push_back(csv.number(row, rgbCols[k]));
  }
  std::map<std::string, Observer, std::less<>> cameras;
  for (auto& [name, c] : byCamera) {
    checkIncreasingWavelengths(csv.path(), c.lambdas, c.lines);
    Observer obs{name, true, {}};
    for (std::size_t k = 0; k < 3; ++k)
      obs.curves[k] = TabulatedSpectrum(c.lambdas, c.rgb[k], Extrapolation::Zero).toDense();
    cameras.emplace(name, std::move(obs));
  }
  return cameras;
}

struct Registry {
  Observer cie1931 = loadCie("cie1931", "cie1931_2deg.csv");
  Observer cie1964 = loadCie("cie1964", "cie1964_10deg.csv");
  std::map<std::string, Observer, std::less<>> cameras = loadCameras();
};

const Registry& registry() {
  static const Registry instance;
  return instance;
}

}  // namespace

Eigen::Vector3d Observer::integrate(const Spectrum& s) const {
  Eigen::Vector3d result;
  for (int c = 0; c < 3; ++c) result[c] = (s * curves[static_cast<std::size_t>(c)]).integral();
  return result;
}

Eigen::Vector3d Observer::at(double lambdaNm) const {
  return {curves[0].at(lambdaNm), curves[1].at(lambdaNm), curves[2].at(lambdaNm)};
}

const Observer& observer(std::string_view name) {
  const Registry& r = registry();
  if (name == "cie1931") return r.cie1931;
  if (name == "cie1964") return r.cie1964;
  if (auto it = r.cameras.find(name); it != r.cameras.end()) return it->second;
  std::vector<std::string> names{"cie1931", "cie1964"};
  for (const auto& [camera, curves] : r.cameras) names.push_back(camera);
  throw Error("unknown observer '" + excerpt(name) + "'" + caseHint(name, names) +
              " (see `prism colour list observers`)");
}

const Observer& cie1931Observer() { return registry().cie1931; }

std::vector<std::string> listObservers() {
  std::vector<std::string> names{"cie1931", "cie1964"};
  for (const std::string& camera : listCameras()) names.push_back(camera);
  return names;
}

std::vector<std::string> listCameras() {
  std::vector<std::string> names;
  for (const auto& [name, obs] : registry().cameras) names.push_back(name);
  return names;
}

Eigen::Vector3d reflectanceTristimulus(const Observer& obs, const Spectrum& reflectance,
                                       const Spectrum& illuminant) {
  double norm = (illuminant * obs.curves[1]).integral();
  return obs.integrate(reflectance * illuminant) / norm;
}

Eigen::Vector3d whiteTristimulus(const Observer& obs, const Spectrum& illuminant) {
  return reflectanceTristimulus(obs, Spectrum::constant(1.0), illuminant);
}

std::vector<Eigen::Vector3d> reflectanceWeights(const Observer& obs, const Spectrum& illuminant) {
  // The integral of each 1 nm node i through Spectrum::integral's trapezoid rule is the
  // integrand's value there times 1 nm, halved at both ends.
  double norm = (illuminant * obs.curves[1]).integral();
  std::vector<Eigen::Vector3d> weights;
  for (int i = 0; i < kSpectrumSamples; ++i) {
    double trapezoid = (i == 0 || i == kSpectrumSamples - 1) ? 0.5 : 1.0;
    weights.push_back(Eigen::Vector3d(obs.curves[0][i], obs.curves[1][i], obs.curves[2][i]) *
                      (trapezoid * illuminant[i] / norm));
  }
  return weights;
}

double absoluteTristimulusScale(const Observer& obs) {
  const double kLumensPerWatt = shared::kLumensPerWatt;
  if (!obs.isCamera) return kLumensPerWatt;
  static const Spectrum d65 = illuminant("D65");
  return kLumensPerWatt * observer("cie1931").integrate(d65).y() / obs.integrate(d65).y();
}

double luminousIntegral(const Spectrum& spd) { return luminousTristimulus(spd)[1]; }

Eigen::Vector3d luminousTristimulus(const Spectrum& spd) {
  return double(shared::kLumensPerWatt) * cie1931Observer().integrate(spd);
}

}  // namespace prism
