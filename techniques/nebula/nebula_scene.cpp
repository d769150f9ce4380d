#include "techniques/nebula/nebula_scene.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <iterator>
#include <sstream>
#include <utility>

#include <fmt/format.h>

#include "core/error.h"
#include "core/input_file.h"
#include "core/json_schema.h"

namespace prism::nebula {

namespace {

glm::dvec3 dvec3(const schema::Node& n, const schema::Range& range = schema::Range::any()) {
  auto v = n.numbers(3, range);
  return {v[0], v[1], v[2]};
}

// The least peak of a scattering spectrum's shape (its amount is "scattering").
constexpr double kMinScatteringPeak = 1e-30;

// P_σ: "grey", "ccm", or the coefficients c₀ … c₃ of c₀ + c₁λ + … (λ in µm), ≥ 0 on the band.
PolynomialPiece readScatteringSpectrum(const schema::Node& n) {
  if (n.json().is_string()) {
    const std::string name = n.string();
    if (name == "grey") return greyScattering();
    if (name == "ccm") return ccmScattering();
    n.fail("must be 'grey', 'ccm' or 1 to 4 polynomial coefficients, not '" + excerpt(name) + "'");
  }
  const std::size_t count = n.arraySize();
  if (count < 1 || count > 4) n.fail(fmt::format("expected 1 to 4 polynomial coefficients (up to a cubic), got {}", count));
  PolynomialPiece p = greyScattering();
  for (std::size_t i = 0; i < count; ++i) p.coeffs[i] = n.element(i).number(schema::Range::any().forFloat());
  double lowest = 0.0, lowestAt = 0.0, highest = 0.0;  // the most negative value over the band, if any
  for (int i = 0; i <= 400; ++i) {
    const double lambdaUm = kBandLoUm + (kBandHiUm - kBandLoUm) * i / 400.0;
    const double v = p.at(lambdaUm);
    if (!(v >= lowest)) lowest = v, lowestAt = lambdaUm;
    highest = std::max(highest, v);
  }
  if (!(lowest >= 0.0))
    n.fail(fmt::format("the scattering spectrum is {:.3g} at {:.0f} nm: it must be ≥ 0 over {:.0f}–{:.0f} nm", lowest,
                       lowestAt * 1000.0, kBandLoUm * 1000.0, kBandHiUm * 1000.0));
  // None at all left the starlight's basis without a direction (a singular Gram matrix, after the
  // precomputation); a peak of 1e-30 renders, and below it a shape is refused rather than trusted
  // to the Gram matrix's range: "scattering" says how much, this only its shape.
  if (!(highest >= kMinScatteringPeak))
    n.fail(fmt::format("the scattering spectrum peaks at {:.3g} over {:.0f}–{:.0f} nm, below {:g}: it has no shape; for no "
                       "scattering give \"scattering\": 0",
                       highest, kBandLoUm * 1000.0, kBandHiUm * 1000.0, kMinScatteringPeak));
  return p;
}

}  // namespace

DensitySource readNebulaKeys(const schema::Node& n, NebulaModel& m, int& steps) {
  DensitySource source;
  schema::Node density = n.child("density");
  density.expectObject({"noise", "file"});
  if (density.has("noise") == density.has("file")) density.fail("give exactly one of 'noise' and 'file'");
  if (auto noise = density.optionalChild("noise")) {
    noise->expectObject({"resolution", "octaves", "frequency", "amplitude", "gain", "bias", "seed"});
    NoiseParameters p;
    if (noise->has("resolution")) p.resolution = noise->child("resolution").integer(schema::Range::closed(2, 512));
    if (noise->has("octaves")) p.octaves = noise->child("octaves").integer(schema::Range::closed(1, 16));
    p.frequency = noise->number("frequency", p.frequency, schema::Range::above(0.0).forFloat());
    p.amplitude = noise->number("amplitude", p.amplitude, schema::Range::atLeast(0.0).forFloat());
    p.gain = noise->number("gain", p.gain, schema::Range::closed(0.0, 1.0));
    p.bias = noise->number("bias", p.bias, schema::Range::closed(-10.0, 10.0));
    if (noise->has("seed")) p.seed = static_cast<std::uint64_t>(noise->child("seed").integer(schema::Range::atLeast(0)));
    source.noise = p;
  } else {
    schema::Node file = density.child("file");
    std::filesystem::path dir = std::filesystem::path(n.document().name).parent_path();
    if (dir.empty()) dir = ".";
    const std::string name = file.string();  // its own error names the place: outside the try
    try {
      source.file = schema::confinedFile(dir, dir, name);
    } catch (const Error& e) {
      file.fail(e.what());
    }
    m.density = readDensityFile(source.file);
  }
  m.extinction = n.number("extinction", m.extinction, schema::Range::atLeast(0.0).forFloat());
  m.scattering = n.number("scattering", m.scattering, schema::Range::atLeast(0.0).forFloat());
  if (auto spectrum = n.optionalChild("scattering_spectrum")) m.scatteringSpectrum = readScatteringSpectrum(*spectrum);
  m.emission = n.number("emission", m.emission, schema::Range::atLeast(0.0).forFloat());
  if (auto lines = n.optionalChild("lines")) {
    std::vector<std::string_view> allowed(std::begin(kLineGroups), std::end(kLineGroups));
    lines->expectObject(allowed);
    for (const std::string& key : lines->keys())
      m.lineGroups.push_back({key, lines->child(key).number(schema::Range::atLeast(0.0).forFloat())});
  }
  if (auto zones = n.optionalChild("ionisation")) {
    zones->expectObject({"front_radius", "front_width"});
    IonisationModel z;
    z.frontRadius = zones->number("front_radius", z.frontRadius, schema::Range{0.0, kMaxFrontRadius, true, false});
    z.frontWidth = zones->number("front_width", z.frontWidth, schema::Range{0.0, kMaxFrontWidth, true, false});
    m.ionisation = z;
  }
  schema::Node stars = n.child("stars");
  for (std::size_t i = 0; i < stars.arraySize(); ++i) {
    schema::Node s = stars.element(i);
    s.expectObject({"position", "temperature", "luminosity"});
    m.stars.push_back({dvec3(s.child("position"), schema::Range::closed(-100.0, 100.0)),
                       s.child("temperature").number(schema::Range::closed(kMinStarTemperatureK, kMaxStarTemperatureK)),
                       s.number("luminosity", 1.0, schema::Range::atLeast(0.0).forFloat())});
  }
  if (n.has("star_model")) {
    std::string model = n.child("star_model").string();
    if (model == "planck") m.starModel = StarModel::Planck;
    else if (model == "wien") m.starModel = StarModel::Wien;
    else n.child("star_model").fail("must be 'planck' or 'wien', not '" + excerpt(model) + "'");
  }
  if (n.has("filters")) {
    m.filters = n.child("filters").string();
    if (m.filters != "hubble" && m.filters != "cie1931")
      n.child("filters").fail("must be 'hubble' or 'cie1931', not '" + excerpt(m.filters) + "'");
  }
  if (auto bands = n.optionalChild("passbands")) {
    if (bands->arraySize() != 3) bands->fail("expected three passband edits, one per channel");
    for (std::size_t c = 0; c < 3; ++c) {
      schema::Node e = bands->element(c);
      e.expectObject({"shift_nm", "width"});
      m.passbands[c] = {e.number("shift_nm", 0.0, schema::Range::closed(-kMaxPassbandShiftNm, kMaxPassbandShiftNm)),
                        e.number("width", 1.0, schema::Range::closed(kMinPassbandWidthScale, kMaxPassbandWidthScale))};
    }
    try {
      editedFilterSet(filterSet(m.filters), m.passbands);
    } catch (const Error& e) {
      bands->fail(e.what());
    }
  }
  if (n.has("steps")) steps = n.child("steps").integer(schema::Range::closed(1, kMaxSteps));
  return source;
}

NebulaSceneFile readNebulaScene(const std::filesystem::path& path) {
  requireInputFile(path, "a nebula scene");
  std::ifstream in(path, std::ios::binary);
  if (!in) throw Error(FileLocation{path.string()}, "cannot open the scene file");
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  schema::Document doc{path.string(), {}};
  nlohmann::json json = schema::parseJson(text, doc.name);
  schema::Node root(json, "", doc);
  if (json.is_object() && json.contains("camera"))  // said before "/camera: unknown key", nebula or not
    root.fail("a scene of the renderer (it has a camera): `prism render` and `prism view` take it; `prism nebula` "
              "takes a file whose only key is \"nebula\"");
  root.expectObject({"nebula"});
  schema::Node n = root.child("nebula");
  n.expectObject({"density", "extinction", "scattering", "scattering_spectrum", "emission", "lines", "ionisation",
                  "stars", "star_model", "filters", "passbands", "camera", "steps"});
  NebulaSceneFile file;
  NebulaModel& m = file.scene.model;
  file.source = readNebulaKeys(n, m, file.scene.steps);
  if (auto cam = n.optionalChild("camera")) {
    cam->expectObject({"position", "target", "fov", "width", "height"});
    if (cam->has("position")) m.camera.position = dvec3(cam->child("position"), schema::Range::closed(-100.0, 100.0));
    if (cam->has("target")) m.camera.target = dvec3(cam->child("target"), schema::Range::closed(-100.0, 100.0));
    m.camera.fovYDeg = cam->number("fov", m.camera.fovYDeg, schema::Range::open(0.0, 180.0));
    if (cam->has("width")) m.camera.width = cam->child("width").integer(schema::Range::closed(1, kMaxImageSide));
    if (cam->has("height")) m.camera.height = cam->child("height").integer(schema::Range::closed(1, kMaxImageSide));
    if (glm::length(m.camera.target - m.camera.position) <= 0.0) cam->fail("position and target must differ");
  }
  return file;
}

glm::ivec3 NebulaSceneFile::densitySize() const {
  if (source.noise) return glm::ivec3(source.noise->resolution);
  const DensityGrid& d = scene.model.density;
  return {d.nx, d.ny, d.nz};
}

NebulaScene generateDensity(NebulaSceneFile file, unsigned threads, const DensityProgress& progress) {
  if (file.source.noise) file.scene.model.density = generateFbm(*file.source.noise, threads, progress);
  return std::move(file.scene);
}

NebulaScene loadNebulaScene(const std::filesystem::path& path, unsigned threads) {
  return generateDensity(readNebulaScene(path), threads);
}

NebulaModel benchNebulaModel(int stars) {
  NebulaModel m;
  NoiseParameters noise;
  noise.resolution = 32;
  noise.seed = 7;
  m.density = generateFbm(noise, 0);
  m.extinction = 3.0;
  m.filters = "hubble";
  for (int i = 0; i < stars; ++i) {  // spread on a ring around the centre, 4000–30000 K
    double t = 2.0 * 3.14159265358979 * i / stars;
    m.stars.push_back({{0.5 + 0.25 * std::cos(t), 0.5 + 0.1 * std::sin(3 * t), 0.5 + 0.25 * std::sin(t)},
                       4000.0 + 26000.0 * i / std::max(1, stars - 1), 1.0});
  }
  m.camera.width = m.camera.height = 64;
  return m;
}

}  // namespace prism::nebula
