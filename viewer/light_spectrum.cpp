#include "viewer/light_spectrum.h"

#include <fmt/format.h>

#include "scene/scene_loader.h"
#include "core/error.h"
#include "core/file_extension.h"
#include "spectral/spectrum_csv.h"
#include "spectral/illuminant.h"

namespace prism::viewer {

void setLightSpectrum(Light& light, const Spectrum& spd, const std::string& label) {
  try {
    light.spd = normalisedLightSpectrum(spd);
  } catch (const Error& e) {
    throw Error(fmt::format("{}: {}", label, e.what()));
  }
  light.spdLabel = label;
}

void setLightSpdFromCsv(Light& light, const std::string& path) {
  setLightSpectrum(light, readLampCsv(path), "csv:" + path);
}

void setLightSpd(Light& light, const std::string& name) {
  setLightSpectrum(light, lampSpectrum(name), lowercaseExtension(name) == ".csv" ? "csv:" + name : name);
}

}  // namespace prism::viewer
