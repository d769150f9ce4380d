#include "techniques/prt/prt_section.h"

#include <cmath>
#include <mutex>

#include <fmt/format.h>
#include <glm/gtc/matrix_transform.hpp>

#include "core/error.h"
#include "core/file_extension.h"
#include "core/fnv1a.h"
#include "core/json_schema.h"
#include "shared_cpp.h"
#include "imaging/exr_file.h"
#include "imaging/radiance_hdr.h"
#include "spectral/colour_space.h"
#include "spectral/illuminant.h"
#include "spectral/observer.h"
#include "spectral/rgb_intent.h"
#include "techniques/prt/prt_environment_radiance.h"
#include "techniques/prt/prt_sky_cache.h"

namespace prism::prt {
namespace {

std::shared_ptr<const PrtMap> readMap(const schema::Node& n) {
  std::filesystem::path folder = std::filesystem::path(n.document().name).parent_path();
  if (folder.empty()) folder = ".";
  auto map = std::make_shared<PrtMap>();
  const std::string name = n.string();  // its own error names the place: outside the try
  try {
    map->file = schema::confinedFile(folder, folder, name);
    imaging::FloatImage image = readEnvironmentMap(map->file);
    map->width = image.width;
    map->height = image.height;
    map->linearRgb.reserve(3 * image.pixelCount());
    for (int y = 0; y < image.height; ++y) {
      for (int x = 0; x < image.width; ++x) {
        for (int c = 0; c < 3; ++c) {
          float v = image.at(x, y, c);
          if (!std::isfinite(v) || v < 0.0f || v > schema::kFloatInputLimit)
            throw Error(fmt::format("{}: texel ({}, {}): channel {} is {}, not a radiance within 0..{:g}", name, x, y, c,
                                    v, schema::kFloatInputLimit));
          map->linearRgb.push_back(v);
        }
      }
    }
  } catch (const Error& e) {
    n.fail(e.what());
  }
  return map;
}

}  // namespace

imaging::FloatImage readEnvironmentMap(const std::filesystem::path& file) {
  const std::string extension = lowercaseExtension(file);
  if (extension == ".hdr") return imaging::readRadianceHdr(file);
  if (extension != ".exr")
    throw Error(fmt::format("{}: an environment map is an OpenEXR (.exr) or Radiance (.hdr) file", file.string()));
  imaging::ExrImage exr = imaging::readExr(file);
  if (exr.colour != imaging::ColourMeaning::LinearSrgb || exr.image.channels < 3)
    throw Error(fmt::format("{}: an environment map must be linear sRGB (Rec. 709, D65) RGB, not {} with {} channel(s)",
                            file.string(), imaging::colourMeaningName(exr.colour), exr.image.channels));
  return std::move(exr.image);
}

double gridLuminance(const Spectrum& spd) {
  return sampleOnGrid(spd).dot(observerOnGrid(cie1931Observer()).col(1)) * kGridStepNm;
}

Spectrum environmentIlluminant(const std::string& name) {
  Spectrum spd = illuminant(name);
  // PRT's grid is 380–780 nm every 5 nm and the luminance is set on it: a light outside it was
  // scaled by 1/0 (black objects) or, mostly outside, came out of another colour in each mode; a
  // line narrower than the step between two nodes (led:452:1) is lost the same way.
  const double onGrid = gridLuminance(spd), whole = luminousIntegral(spd) / double(shared::kLumensPerWatt);
  if (!(onGrid >= kMinGridLuminanceShare * whole))
    throw Error(fmt::format("{} has {:.3g} % of its luminance on PRT's grid, {}–{} nm every {:g} nm (at least {:g} %: "
                            "the rest, outside it or between its nodes, is lost)",
                            name, 100.0 * onGrid / whole, kGridMinNm, kGridMinNm + (kGridWavelengths - 1) * kGridStepNm,
                            kGridStepNm, 100.0 * kMinGridLuminanceShare));
  return spd;
}

std::string_view prtModeName(PrtMode mode) {
  switch (mode) {
    case PrtMode::Spectral: return "spectral";
    case PrtMode::RgbPrt: return "rgb-prt";
    case PrtMode::Reference5nm: return "reference-5nm";
  }
  return "?";
}

void PrtSection::requireObserver(const Observer& observer, bool referenceMode) const {
  if (mode == PrtMode::RgbPrt && !referenceMode) requireRgbPrtObserver(observer);
}

TechniqueBlock PrtSection::pack(const FramePackInput&) const {
  TechniqueBlock block;
  block.key = kKey;
  return block;
}

std::shared_ptr<const TechniqueEnvironment> PrtSection::environment(const RgbToSpectrumTable& table) const {
  return environmentRadiance(*this, table);
}

std::vector<std::filesystem::path> PrtSection::inputFiles() const {
  if (!map) return {};
  return {map->file};
}

std::uint64_t PrtSection::hashLoadedData(std::uint64_t hash) const {
  if (!map) return hash;
  const std::int32_t size[2] = {map->width, map->height};
  hash = fnv1a(size, sizeof size, hash);
  return fnv1a(map->linearRgb.data(), map->linearRgb.size() * sizeof(float), hash);
}

std::optional<TechniqueLight> PrtSection::light() const {
  if (!sky || !sky->sunDisc) return std::nullopt;
  std::shared_ptr<const SkyRadianceGrid> grid = sectionSky(*sky);
  // PRT's frame (z up) turned about the zenith, then the world's (y up): (x, y, z) → (x, z, −y).
  const glm::dvec3 p = glm::dmat3(glm::rotate(glm::dmat4(1.0), glm::radians(static_cast<double>(rotationDeg)),
                                              glm::dvec3(0.0, 0.0, 1.0))) *
                       grid->sunDirection;
  TechniqueLight sun;
  sun.direction = -glm::normalize(glm::vec3(glm::dvec3(p.x, p.z, -p.y)));
  sun.spd = Spectrum::fromFunction([grid](double lambdaNm) {
    return lambdaNm < kGridMinNm || lambdaNm > kGridMinNm + kGridStepNm * (kGridWavelengths - 1) ? 0.0
                                                                                                 : grid->sunIrradianceAt(lambdaNm);
  });
  sun.spdLabel = "sun through the spectral sky (PRT)";
  sun.followsSection = true;
  if (!(gridLuminance(sun.spd) > 0.0)) {  // below the horizon: out, with the solar spectrum's shape
    sun.spd = atmosphere::solarIrradianceSpectrum().toDense();
    sun.illuminanceLux = 0.0;
  }
  return sun;
}

TechniqueBench PrtSection::bench(std::size_t /*pointAndSpotLights*/) const {
  auto spectral8 = std::make_shared<PrtSection>(*this);
  spectral8->mode = PrtMode::Spectral;
  spectral8->basis = 8;
  auto rgb = std::make_shared<PrtSection>(*this);
  rgb->mode = PrtMode::RgbPrt;
  // Both in one spectral frame, so that the section's mode decides what the PRT pass draws: the
  // run's RGB frame (the configurations' default) draws RGB-PRT whatever the section says. Under
  // CIE 1931, on which RGB-PRT is defined, whatever the run's observer (its curves change the
  // weights, not the cost).
  const std::vector<std::pair<std::string, std::string>> spectral16 = {
      {"mode", "jakob-hanika"}, {"wavelengths", "16"}, {"observer", "cie1931"}};
  TechniqueBench b;
  b.configs.push_back({"prt m=8", spectral16, false, 0, spectral8});
  b.configs.push_back({"rgb-prt", spectral16, false, 0, rgb});
  b.ratios.push_back({"ratio_spectral8_to_rgb_prt", "prt m=8", "rgb-prt"});
  return b;
}

std::unique_ptr<TechniqueSection> PrtSection::parse(const schema::Node& n, const TechniqueSections& earlier) {
  using schema::Range;
  n.expectObject({"environment", "basis", "mode", "samples", "shadows"});
  auto s = std::make_unique<PrtSection>();
  if (auto e = n.optionalChild("environment")) {
    e->expectObject({"illuminant", "shape", "map", "atmosphere", "luminance", "rotation_deg"});
    if (auto m = e->optionalChild("map")) {
      for (const char* other : {"illuminant", "shape", "atmosphere"})
        if (e->has(other)) e->child(other).fail("give one of a map, an atmosphere, or an illuminant and shape");
      s->map = readMap(*m);
    }
    if (auto a = e->optionalChild("atmosphere")) {
      for (const char* other : {"illuminant", "shape", "luminance"})
        if (e->has(other))
          e->child(other).fail("the spectral sky's radiance is absolute (its sun's): give an atmosphere or an illuminant, shape and luminance");
      PrtSky sky;
      atmosphere::readAtmosphereKeys(*a, sky.atmosphere, {"sun_disc"});
      sky.sunDisc = a->boolean("sun_disc", true);
      // Its sun would be a second light beside the atmosphere section's, lighting every object twice.
      if (sky.sunDisc && earlier.has("atmosphere"))
        (a->has("sun_disc") ? a->child("sun_disc") : *a)
            .fail("the scene's atmosphere section adds its sun to every object, PRT's too: set sun_disc to false here, "
                  "or the scene is lit by two suns");
      s->sky = sky;
    }
    if (auto i = e->optionalChild("illuminant")) {
      s->illuminant = i->string();
      try {
        environmentIlluminant(s->illuminant);
      } catch (const Error& err) {
        i->fail(err.what());
      }
    }
    if (auto sh = e->optionalChild("shape")) {
      s->shape = sh->string();
      if (s->shape != "sky" && s->shape != "uniform") sh->fail("expected \"sky\" or \"uniform\", got \"" + s->shape + "\"");
    }
    s->luminanceCdM2 = e->numberF("luminance", s->luminanceCdM2, Range::above(0.0));
    s->rotationDeg = e->numberF("rotation_deg", 0.0f, Range::closed(-360.0, 360.0));
  }
  if (auto b = n.optionalChild("basis")) s->basis = b->integer(Range::closed(1, shared::kPrtMaxBasis));
  if (auto m = n.optionalChild("mode")) {
    std::string name = m->string();
    bool found = false;
    for (PrtMode mode : {PrtMode::Spectral, PrtMode::RgbPrt, PrtMode::Reference5nm}) {
      if (name == prtModeName(mode)) {
        s->mode = mode;
        found = true;
      }
    }
    if (!found) m->fail("expected \"spectral\", \"rgb-prt\" or \"reference-5nm\", got \"" + name + "\"");
  }
  if (auto m = n.optionalChild("samples")) s->samples = m->integer(Range::closed(1, 1 << 20));
  s->shadows = n.boolean("shadows", true);
  return s;
}

SpectralEnvironment sectionEnvironment(const PrtSection& section, const RgbToSpectrumTable& srgbTable,
                                       bool sunInEnvironment) {
  SpectralEnvironment environment;
  if (section.map) {
    // A texel is light: (1, 1, 1) is the map's white, D65 (the illuminant intent, as a background's).
    auto toSpectrum = [&srgbTable](const glm::vec3& rgb) {
      return RgbIlluminantSpectrum(srgbTable, colourSpace(srgbTable.gamut()), rgb).toDense();
    };
    double scale = section.luminanceCdM2 / gridLuminance(toSpectrum(glm::vec3(1.0f)));
    environment = equirectangularEnvironment(section.map->file.string(), section.map->width, section.map->height,
                                             section.map->linearRgb,
                                             [&](const glm::vec3& rgb) { return toSpectrum(rgb) * scale; });
  } else if (section.sky) {
    const bool sun = sunInEnvironment && section.sky->sunDisc;
    environment = skyEnvironment(fmt::format("spectral sky, sun at {:g}° elevation, {:g}° azimuth{}",
                                             section.sky->atmosphere.sunElevationDeg, section.sky->atmosphere.sunAzimuthDeg,
                                             sun ? ", its disc on SH-5" : section.sky->sunDisc ? "" : ", no sun disc"),
                                 *sectionSky(*section.sky), sun, double(shared::kLumensPerWatt));
  } else {
    Spectrum spd = environmentIlluminant(section.illuminant);
    spd *= section.luminanceCdM2 / gridLuminance(spd);
    environment = section.shape == "uniform" ? uniformEnvironment(section.illuminant + " uniform", spd)
                                             : skyGradientEnvironment(section.illuminant + " sky", spd);
  }
  if (section.rotationDeg != 0.0f) {
    // The scene's up (+y) is PRT's zenith (+z): a turn about the zenith is the same angle.
    glm::dmat3 rotation(glm::rotate(glm::dmat4(1.0), glm::radians(static_cast<double>(section.rotationDeg)),
                                    glm::dvec3(0.0, 0.0, 1.0)));
    environment = rotateEnvironment(environment, rotation);
  }
  return environment;
}

std::string environmentKey(const PrtSection& section) {
  std::string key = fmt::format("{}|{}|{}|{}|{}", section.illuminant, section.shape,
                                static_cast<const void*>(section.map.get()), section.luminanceCdM2, section.rotationDeg);
  if (section.sky) {
    const atmosphere::AtmosphereSky& a = section.sky->atmosphere;
    const atmosphere::AtmosphereParameters& p = a.parameters;
    key += fmt::format("|sky {} {} {} {}|{} {} {} {} {} {} {} {} {} {} {} {} {} {} {} {}", a.sunElevationDeg,
                       a.sunAzimuthDeg, a.groundAltitudeM, section.sky->sunDisc, p.bottomRadiusKm, p.topRadiusKm,
                       p.rayleighScaleHeightKm, p.rayleighScatteringPerKm, p.aerosols, p.mieScaleHeightKm,
                       p.mieAngstromAlpha, p.mieAngstromBeta, p.mieSingleScatteringAlbedo, p.miePhaseG, p.ozoneColumnDu,
                       p.ozonePeakAltitudeKm, p.ozoneHalfWidthKm, p.groundAlbedo, p.sunAngularRadiusRad,
                       p.multipleScattering);
  }
  return key;
}

std::shared_ptr<const SkyRadianceGrid> sectionSky(const PrtSky& sky) {
  static std::mutex mutex;
  static std::optional<PrtSky> lastSky;
  static std::shared_ptr<const SkyRadianceGrid> lastGrid;
  std::lock_guard lock(mutex);
  const atmosphere::AtmosphereSky& a = sky.atmosphere;
  if (!lastSky || !(lastSky->atmosphere.parameters == a.parameters) ||
      lastSky->atmosphere.sunElevationDeg != a.sunElevationDeg || lastSky->atmosphere.sunAzimuthDeg != a.sunAzimuthDeg ||
      lastSky->atmosphere.groundAltitudeM != a.groundAltitudeM) {
    lastGrid = std::make_shared<const SkyRadianceGrid>(cachedSky(sky));
    lastSky = sky;
  }
  return lastGrid;
}

}  // namespace prism::prt
