#include "techniques/underwater/jerlov_water.h"

#include <fmt/format.h>

#include "core/csv.h"
#include "core/data_files.h"
#include "core/error.h"

namespace prism::underwater {
namespace {

const char* fileOf(JerlovDataset dataset) {
  return dataset == JerlovDataset::SolonenkoMobley2015 ? "jerlov_iop_10types.csv"
                                                       : "jerlov_iop_williamson2022.csv";
}

std::string joined(const std::vector<std::string>& names) {
  std::string out;
  for (const std::string& n : names) out += (out.empty() ? "" : ", ") + n;
  return out;
}

}  // namespace

JerlovDataset jerlovDatasetFromName(std::string_view name) {
  if (name == "jerlov") return JerlovDataset::SolonenkoMobley2015;
  if (name == "williamson2022") return JerlovDataset::WilliamsonHollins2022;
  throw Error(fmt::format("unknown water data set \"{}\" (known: jerlov, williamson2022)", name));
}

std::string_view jerlovDatasetName(JerlovDataset dataset) {
  return dataset == JerlovDataset::SolonenkoMobley2015 ? "jerlov" : "williamson2022";
}

std::vector<std::string> listJerlovTypes(JerlovDataset dataset) {
  CsvTable csv = CsvTable::read(dataFile(fileOf(dataset)));
  int typeColumn = csv.column("water_type");
  std::vector<std::string> types;
  for (const CsvRow& row : csv.rows()) {
    const std::string& type = row.fields[static_cast<std::size_t>(typeColumn)];
    if (types.empty() || types.back() != type) types.push_back(type);
  }
  return types;
}

WaterProperties jerlovWater(std::string_view type, JerlovDataset dataset) {
  CsvTable csv = CsvTable::read(dataFile(fileOf(dataset)));
  const bool williamson = dataset == JerlovDataset::WilliamsonHollins2022;
  int typeColumn = csv.column("water_type"), lambdaColumn = csv.column("wavelength_nm");
  int bColumn = csv.column("scattering_b_per_m"), kdColumn = csv.column("kd_per_m");
  // Solonenko & Mobley give a; Williamson & Hollins give the extinction c, and a = c − b.
  int aOrCColumn = csv.column(williamson ? "extinction_c_per_m" : "absorption_a_per_m");
  std::vector<double> lambdas, a, b, kd;
  std::vector<int> lines;
  for (const CsvRow& row : csv.rows()) {
    if (row.fields[static_cast<std::size_t>(typeColumn)] != type) continue;
    double scattering = csv.number(row, bColumn), aOrC = csv.number(row, aOrCColumn);
    double absorption = williamson ? aOrC - scattering : aOrC;
    double attenuation = csv.number(row, kdColumn);
    if (absorption < 0.0 || scattering < 0.0 || attenuation < 0.0) {
      throw Error(fmt::format("{}:{}: negative coefficient for water type {}", csv.path(), row.line, type));
    }
    lambdas.push_back(csv.number(row, lambdaColumn));
    a.push_back(absorption);
    b.push_back(scattering);
    kd.push_back(attenuation);
    lines.push_back(row.line);
  }
  if (lambdas.empty()) {
    throw Error(fmt::format("unknown water type \"{}\" in the {} data (known: {})", type,
                            jerlovDatasetName(dataset), joined(listJerlovTypes(dataset))));
  }
  checkIncreasingWavelengths(csv.path(), lambdas, lines);
  auto dense = [&](std::vector<double> values) {
    return TabulatedSpectrum(lambdas, std::move(values), Extrapolation::Clamp).toDense();
  };
  return {std::string(type), dense(std::move(a)), dense(std::move(b)), dense(std::move(kd))};
}

}  // namespace prism::underwater
