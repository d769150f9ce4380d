// Natural waters as oceanographers measure them: the ten Jerlov water types (oceanic I, IA, IB,
// II, III; coastal 1C, 3C, 5C, 7C, 9C) with their absorption a = σa, scattering b = σs and
// diffuse downwelling attenuation Kd per wavelength, from data/jerlov_iop_10types.csv (310–700 nm,
// Solonenko & Mobley 2015's values as sRAT-RT ships them), or the newer measurements of six types
// (IB, II, III, 1C, 3C, 5C; 400–700 nm) of Williamson & Hollins 2022
// (data/jerlov_iop_williamson2022.csv). See data/SOURCES.md.
//
// Between samples, linear. Beyond the tables every coefficient is held at its end value: no
// data set here reaches past 700 nm, where pure water's absorption keeps rising steeply (Pope &
// Fry 1997 measure 0.624 m⁻¹ at 700 nm, the end of their table, and it climbs from 0.448 m⁻¹ at
// 675 nm), so deep red and near infrared light is attenuated less than in real water. It matters little to a CIE observer
// (ȳ at 700 nm is 0.4 % of its peak) and more to a camera with a wide red band.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "spectral/spectrum.h"

namespace prism::underwater {

enum class JerlovDataset { SolonenkoMobley2015, WilliamsonHollins2022 };
JerlovDataset jerlovDatasetFromName(std::string_view name);  // jerlov|williamson2022
std::string_view jerlovDatasetName(JerlovDataset dataset);

struct WaterProperties {
  std::string type;  // e.g. "IB"
  Spectrum sigmaA;   // absorption, 1/m
  Spectrum sigmaS;   // scattering, 1/m
  Spectrum kd;       // diffuse attenuation of downwelling irradiance, 1/m
};

// The types a data set has, in its order. Error naming the file and place on bad data.
std::vector<std::string> listJerlovTypes(JerlovDataset dataset = JerlovDataset::SolonenkoMobley2015);
// Error listing the known types when the data set has no such type.
WaterProperties jerlovWater(std::string_view type,
                            JerlovDataset dataset = JerlovDataset::SolonenkoMobley2015);

}  // namespace prism::underwater
