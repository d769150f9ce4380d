#include "spectral/illuminant.h"

#include <charconv>
#include <cmath>

#include "spectral/spectrum_csv.h"
#include "core/data_files.h"
#include "core/error.h"
#include "core/file_extension.h"
#include "core/name_case.h"

namespace prism {
namespace {

struct Tables {
  SpectraTable aD65 = SpectraTable::read(dataFile("cie_illuminants_A_D65_1nm.csv"),
                                         std::vector<std::string_view>{"A", "D65"});
  SpectraTable daylightTabulated = SpectraTable::read(dataFile("cie_illuminants_D_5nm.csv"));
  SpectraTable daylightComponents =
      SpectraTable::read(dataFile("daylight_components.csv"),
                         std::vector<std::string_view>{"S0", "S1", "S2"});
  SpectraTable fluorescent = SpectraTable::read(dataFile("illuminants_F.csv"));
  SpectraTable led = SpectraTable::read(dataFile("illuminants_LED.csv"));
  SpectraTable ledGlobe = SpectraTable::read(dataFile("led_globe_a19_lspdd.csv"));
  SpectraTable nist = SpectraTable::read(dataFile("light_sources_nist_cqs.csv"));
};

const Tables& tables() {
  static const Tables instance;
  return instance;
}

// A number following a "prefix:" in an illuminant name; Error naming the whole name otherwise.
double parameter(std::string_view name, std::string_view text) {
  double value = 0.0;
  auto result = std::from_chars(text.data(), text.data() + text.size(), value);
  if (result.ec != std::errc() || result.ptr != text.data() + text.size() || !std::isfinite(value))
    throw Error("illuminant '" + excerpt(name) + "': '" + excerpt(text) +
                "' is not a number");
  return value;
}

Spectrum scaledTo100At560(Spectrum s) { return s * (100.0 / s.at(560.0)); }

}  // namespace

Spectrum daylight(double cctK) {
  if (!(cctK >= 4000.0 && cctK <= 25000.0))
    throw Error("daylight: correlated colour temperature must be within 4000–25000 K, got " + shortestNumber(cctK));
  // CIE 15:2004 Eqs. 3.3–3.5 (chromaticity of daylight), 3.6 (M1, M2, rounded to three
  // decimals as CIE 15:2004 §3.1 prescribes, which is what makes 6504 K reproduce D65).
  double t = cctK;
  double xD = t <= 7000.0 ? -4.6070e9 / (t * t * t) + 2.9678e6 / (t * t) + 0.09911e3 / t + 0.244063
                          : -2.0064e9 / (t * t * t) + 1.9018e6 / (t * t) + 0.24748e3 / t + 0.237040;
  double yD = -3.000 * xD * xD + 2.870 * xD - 0.275;
  double m = 0.0241 + 0.2562 * xD - 0.7341 * yD;
  double m1 = std::round((-1.3515 - 1.7703 * xD + 5.9114 * yD) / m * 1000.0) / 1000.0;
  double m2 = std::round((0.0300 - 31.4424 * xD + 30.0717 * yD) / m * 1000.0) / 1000.0;
  const SpectraTable& c = tables().daylightComponents;
  TabulatedSpectrum s0 = c.spectrum("S0", Extrapolation::Zero);
  TabulatedSpectrum s1 = c.spectrum("S1", Extrapolation::Zero);
  TabulatedSpectrum s2 = c.spectrum("S2", Extrapolation::Zero);
  // Combined at the 5 nm nodes, then interpolated linearly (CIE 15:2004 §3.1 note 3).
  std::vector<double> values;
  for (std::size_t i = 0; i < s0.values().size(); ++i)
    values.push_back(s0.values()[i] + m1 * s1.values()[i] + m2 * s2.values()[i]);
  std::vector<double> lambdas(s0.lambdasNm().begin(), s0.lambdasNm().end());
  return TabulatedSpectrum(std::move(lambdas), std::move(values), Extrapolation::Zero).toDense();
}

Spectrum blackbodyIlluminant(double temperatureK) {
  // Below 500 K a body gives no light that 360–830 nm carries in floats once scaled at 560 nm
  // (at 1 K its 560 nm radiance underflows to 0); above 10⁶ K its shape no longer changes.
  if (!(temperatureK >= 500.0 && temperatureK <= 1e6))
    throw Error("blackbody: temperature must be within 500–1000000 K, got " + shortestNumber(temperatureK));
  return scaledTo100At560(blackbody(temperatureK));
}

Spectrum narrowbandLed(double peakNm, double widthNm) {
  if (!(peakNm >= kLambdaMinNm && peakNm <= kLambdaMaxNm))
    throw Error("led: peak wavelength must be within 360–830 nm, got " + shortestNumber(peakNm));
  // Spectra are sampled at whole nanometres: narrower, the samples miss the line (0.01 nm at 700 nm
  // was one sample, and a white with no Z made CIELAB NaN), and their sum is no longer its integral.
  if (!(widthNm >= 1.0 && widthNm <= 200.0))
    throw Error("led: spectral width must be within 1–200 nm (spectra are sampled at whole nm), got " + shortestNumber(widthNm));
  return Spectrum::fromFunction([=](double lambdaNm) {
    double d = (lambdaNm - peakNm) / widthNm;
    double g = std::exp(-d * d);
    return (g + 2.0 * std::pow(g, 5.0)) / 3.0;
  });
}

Spectrum illuminant(std::string_view name) {
  const Tables& t = tables();
  if (name == "A" || name == "D65") return t.aD65.spectrum(name, Extrapolation::Zero).toDense();
  if (t.daylightTabulated.contains(name))
    return t.daylightTabulated.spectrum(name, Extrapolation::Zero).toDense();
  if (t.fluorescent.contains(name)) return t.fluorescent.spectrum(name, Extrapolation::Zero).toDense();
  if (t.led.contains(name)) return t.led.spectrum(name, Extrapolation::Zero).toDense();
  if (name == "led-globe-a19")
    return t.ledGlobe.spectrum("relative_power", Extrapolation::Zero).toDense();
  auto suffix = [&](std::string_view prefix) -> std::string_view {
    return name.substr(0, prefix.size()) == prefix ? name.substr(prefix.size()) : std::string_view{};
  };
  if (std::string_view lamp = suffix("nist:"); !lamp.empty()) {
    if (!t.nist.contains(lamp)) {
      std::vector<std::string> lamps;
      for (const std::string& n : t.nist.names()) lamps.push_back("nist:" + n);
      throw Error("unknown illuminant '" + excerpt(name) + "'" + caseHint(name, lamps) +
                  " (no such lamp in the NIST set; see `prism colour list illuminants`)");
    }
    return t.nist.spectrum(lamp, Extrapolation::Zero).toDense();
  }
  if (std::string_view k = suffix("daylight:"); !k.empty()) return daylight(parameter(name, k));
  if (std::string_view k = suffix("blackbody:"); !k.empty())
    return blackbodyIlluminant(parameter(name, k));
  if (std::string_view led = suffix("led:"); !led.empty()) {
    std::size_t colon = led.find(':');
    if (colon == std::string_view::npos)
      throw Error("illuminant '" + excerpt(name) + "': expected led:<peak nm>:<width nm>");
    return narrowbandLed(parameter(name, led.substr(0, colon)), parameter(name, led.substr(colon + 1)));
  }
  std::vector<std::string> names;
  for (const IlluminantInfo& info : listIlluminants()) names.push_back(info.name);
  throw Error("unknown illuminant '" + excerpt(name) + "'" + caseHint(name, names) +
              " (see `prism colour list illuminants`)");
}

std::vector<IlluminantInfo> listIlluminants() {
  const Tables& t = tables();
  std::vector<IlluminantInfo> list;
  list.push_back({"A", "relative, 100 at 560 nm (CIE 015:2018, 1 nm)"});
  list.push_back({"D65", "relative, 100 at 560 nm (CIE 015:2018, 1 nm)"});
  for (const std::string& n : t.daylightTabulated.names())
    if (n != "D65") list.push_back({n, "relative, 100 at 560 nm (CIE 15:2004, 5 nm)"});
  for (const std::string& n : t.fluorescent.names())
    list.push_back({n, "relative, as tabulated in CIE 15:2004 (5 nm)"});
  for (const std::string& n : t.led.names())
    list.push_back({n, "relative, as tabulated in CIE 015:2018 Table 12 (1 nm)"});
  list.push_back({"led-globe-a19", "relative power as in LSPDD (peak 0.0049 at 457 nm)"});
  for (const std::string& n : t.nist.names())
    list.push_back({"nist:" + n, "relative, each lamp on its source's own scale (NIST CQS 7.4 / RIT)"});
  list.push_back({"daylight:<K>", "CIE daylight, 4000–25000 K, 100 at 560 nm"});
  list.push_back({"blackbody:<K>", "Planck, 100 at 560 nm"});
  list.push_back({"led:<peak>:<width>", "Ohno 2005 single LED, peak 1"});
  return list;
}

Spectrum lampSpectrum(const std::string& nameOrFile) {
  if (lowercaseExtension(nameOrFile) == ".csv") return readLampCsv(nameOrFile);
  return illuminant(nameOrFile);
}

}  // namespace prism
