#include "app/prt_commands.h"

#include "app/colour_commands.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>

#include <fmt/core.h>
#include <glm/gtc/matrix_transform.hpp>
#include <nlohmann/json.hpp>

#include "app/option_error.h"
#include "core/atomic_file.h"
#include "core/error.h"
#include "core/input_file.h"
#include "core/parallel_for.h"
#include "core/file_extension.h"
#include "core/task_split.h"
#include "harness/progress_bar.h"
#include "harness/prt_plot.h"
#include "imaging/float_image.h"
#include "scene/gltf_loader.h"
#include "scene/scene_loader.h"
#include "spectral/colour_space.h"
#include "spectral/illuminant.h"
#include "spectral/rgb_intent.h"
#include "spectral/rgb_to_spectrum_cache.h"
#include "techniques/atmosphere/atmosphere_section.h"
#include "techniques/prt/gpu/prt_scene_mesh.h"
#include "techniques/prt/metamer.h"
#include "techniques/prt/prt_evaluation.h"
#include "techniques/prt/prt_section.h"
#include "techniques/prt/transfer_part.h"

namespace prism::app {
namespace {

// Every mesh of the input as one PRT object (world space, turned from y-up to PRT's z-up; in a
// scene with PRT objects, only those, as the renderer bakes them): each scene material's measured
// reflectance, else its base colour upsampled by the renderers' sRGB table (Jakob–Hanika, the
// albedo intent; textures and conductors are not read: PRT here is diffuse and per vertex).
void checkSamples(int samples) {
  if (samples < 1 || samples > (1 << 20)) throw Error(fmt::format("--samples: {} out of range 1..{}", samples, 1 << 20));
}

struct PrtInput {
  Scene scene;  // as read (a model: its meshes and materials alone)
  prt::PrtObject object;
  const prt::PrtSection* section() const { return scene.techniques.find<prt::PrtSection>(); }
};

PrtInput loadPrtInput(const std::filesystem::path& input, bool withReflectances) {
  requireInputFile(input, "a scene or a glTF model");
  std::string ext = lowercaseExtension(input);
  PrtInput in;
  Scene& scene = in.scene;
  if (ext == ".json") {
    scene = loadScene(input);
  } else if (ext == ".gltf" || ext == ".glb") {
    // Its emission, if any, is dropped below with a warning: any unit will do.
    GltfPlacement placement;
    placement.emissionLuminance = 1.0f;
    appendGltf(input, input.parent_path(), placement, scene);
  } else {
    throw Error(input.string() + ": expected a scene (.json) or a glTF model (.gltf, .glb)");
  }
  prt::PrtObject& object = in.object;
  prt::PrtSceneMesh gathered = prt::prtSceneMesh(scene, prt::PrtMeshes::PrtObjectsElseAll);
  object.mesh = std::move(gathered.mesh);
  object.vertexMaterial = std::move(gathered.vertexMaterial);
  const prt::PrtMesh& mesh = object.mesh;
  if (mesh.indices.empty()) throw Error(input.string() + ": no triangles to bake");
  for (std::size_t i = 0; i < scene.materials.size(); ++i) {
    if ((scene.materials[i].emission || scene.materials[i].emitsRgb()) && std::ranges::find(object.vertexMaterial, static_cast<int>(i)) != object.vertexMaterial.end())
      fmt::print(stderr, "prism: warning: {}: material '{}' emits light, which PRT's transfer does not carry: PRT shades "
                         "it by its reflectance alone\n", input.string(), scene.materials[i].name);
  }
  if (withReflectances) {
    const RgbToSpectrumTable* table = nullptr;
    for (const Material& material : scene.materials) {
      // The report's sums take one reflectance a material: a textured chart came out as its grey.
      const bool used = std::ranges::find(object.vertexMaterial, static_cast<int>(&material - scene.materials.data())) !=
                        object.vertexMaterial.end();
      if (used && (material.spectralTexture || material.baseColourTexture >= 0))
        fmt::print(stderr, "prism: warning: {}: material '{}' has a texture, which the report does not read: it takes "
                           "its {}\n", input.string(), material.name,
                   material.reflectance ? "measured reflectance" : "base colour");
      if (material.reflectance) {
        object.reflectances.push_back(*material.reflectance);
      } else {
        if (!table) table = &rendererRgbToSpectrumTable("srgb");
        object.reflectances.push_back(RgbAlbedoSpectrum(*table, material.baseColour).toDense());
      }
      object.materialNames.push_back(material.name);
    }
    if (object.reflectances.empty()) {
      object.reflectances.push_back(Spectrum::constant(0.8));
      object.materialNames.push_back("default");
    }
    for (int& m : object.vertexMaterial) m = std::min(m, static_cast<int>(object.reflectances.size()) - 1);
  }
  return in;
}

// The bake a command makes for its input: --samples, else the scene's prt.samples, else 1024;
// shadowed unless --no-shadows or the scene's prt.shadows says not — so that `prt bake SCENE`
// fills the cache entry the renderer reads.
prt::BakeSettings bakeSettingsFor(const PrtInput& input, const std::optional<int>& samples, bool shadows) {
  const prt::PrtSection* section = input.section();
  prt::BakeSettings settings{samples.value_or(section ? section->samples : prt::BakeSettings{}.samples),
                             shadows && (!section || section->shadows)};
  checkSamples(settings.samples);
  return settings;
}

std::filesystem::path cacheFolder(const std::string& given) {
  return given.empty() ? cacheDirectory() : std::filesystem::path(given);
}

prt::CachedTransfer transferFor(const prt::PrtMesh& mesh, const prt::BakeSettings& settings, const std::string& cache,
                                unsigned threads = 0) {
  harness::ProgressBar bar("PRT transfer bake");
  return prt::cachedTransfer(
      mesh, settings, cacheFolder(cache), [&bar](std::size_t done, std::size_t total) { bar.update(done, total); },
      [](const std::string& note) { fmt::print(stderr, "prism: {}\n", note); }, threads);
}

// Task I of N's share of the vertices, as a part for `prism merge`.
void runPrtBakePart(const PrtBakeOptions& o, const PrtInput& input, const prt::BakeSettings& settings) {
  if (o.output.empty()) throw Error("--part: give the part's file with -o");
  refuseImageExtension(o.output, "-o", "part of a PRT bake");
  requireNotSceneInput(o.output, input.scene);  // a model's buffer, a reflectance's CSV
  const prt::PrtMesh& mesh = input.object.mesh;
  if (!o.cacheDir.empty()) throw Error("--cache: a part is written to -o (prism merge puts the parts into the cache's file)");
  const TaskIndex task = parseTaskIndex(o.part, "--part");
  const int vertices = static_cast<int>(mesh.positions.size());
  if (task.count > vertices)
    throw Error(fmt::format("--part {}: {} has {} vertices, at most {} tasks", o.part, o.input, vertices, vertices));
  prt::TransferPart part{prt::transferKey(mesh, settings), settings.samples, vertices, shareOf(task, vertices), {}};
  const std::string what = fmt::format("vertices {}:{} of {}", part.vertices.begin, part.vertices.end, vertices);
  if (prt::isTransferPart(o.output)) {
    try {
      prt::TransferPart existing = prt::loadTransferPart(o.output);
      if (existing.key == part.key && existing.vertices == part.vertices) {
        fmt::print("{}: complete ({}), skipped\n", o.output, what);
        return;
      }
    } catch (const Error& e) {
      fmt::print("{}: baking it again ({})\n", o.output, e.what());
    }
  }
  requireWritable(o.output);
  auto start = std::chrono::steady_clock::now();
  {
    harness::ProgressBar bar(fmt::format("PRT transfer bake, part {}", o.part));
    part.transfer = prt::bakeTransfer(mesh, settings, part.vertices,
                                      [&bar](std::size_t done, std::size_t total) { bar.update(done, total); }, o.threads);
  }
  prt::saveTransferPart(o.output, part);
  double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  fmt::print("wrote {} ({}, {} directions each, key {:016x}) in {:.2f} s\n", o.output, what, settings.samples, part.key,
             seconds);
}

nlohmann::json statisticsJson(const prt::DeltaEStatistics& s) {
  return {{"mean_de94", s.mean94}, {"max_de94", s.max94}, {"mean_de2000", s.mean2000}, {"max_de2000", s.max2000}};
}

// An ASCII PLY of the object with per-vertex sRGB colours.
std::string plyText(const prt::PrtObject& object, const std::vector<Eigen::Vector3d>& rgb) {
  std::string text = fmt::format(
      "ply\nformat ascii 1.0\ncomment prism prt report: display sRGB, Bradford to D65\nelement vertex {}\n"
      "property float x\nproperty float y\nproperty float z\nproperty uchar red\nproperty uchar green\n"
      "property uchar blue\nelement face {}\nproperty list uchar int vertex_indices\nend_header\n",
      object.mesh.positions.size(), object.mesh.indices.size() / 3);
  for (std::size_t v = 0; v < rgb.size(); ++v) {
    const glm::vec3& p = object.mesh.positions[v];
    auto byte = [](double c) { return static_cast<int>(std::lround(255.0 * c)); };
    text += fmt::format("{} {} {} {} {} {}\n", p.x, p.y, p.z, byte(rgb[v].x()), byte(rgb[v].y()), byte(rgb[v].z()));
  }
  for (std::size_t i = 0; i < object.mesh.indices.size(); i += 3)
    text += fmt::format("3 {} {} {}\n", object.mesh.indices[i], object.mesh.indices[i + 1], object.mesh.indices[i + 2]);
  return text;
}

}  // namespace

PrtBakeTarget prtBakeTarget(const PrtBakeOptions& o) {
  if (o.samples) checkSamples(*o.samples);
  PrtInput input = loadPrtInput(o.input, false);
  PrtBakeTarget target;
  target.settings = bakeSettingsFor(input, o.samples, o.shadows);
  target.mesh = std::move(input.object.mesh);
  target.key = prt::transferKey(target.mesh, target.settings);
  target.cacheFile = prt::transferCacheFile(cacheFolder(o.cacheDir), target.key);
  return target;
}

void runPrtBake(const PrtBakeOptions& o) {
  setAllThreads(o.threads);  // Embree's BVH build too, not only the bake
  if (o.samples) checkSamples(*o.samples);
  if (!o.output.empty()) requireOtherFile(o.output, o.input, "the input");
  PrtInput input = loadPrtInput(o.input, false);
  const prt::BakeSettings settings = bakeSettingsFor(input, o.samples, o.shadows);
  const prt::PrtMesh& mesh = input.object.mesh;
  if (!o.part.empty()) return runPrtBakePart(o, input, settings);
  if (!o.output.empty()) throw Error("-o: only with --part (a whole bake goes to the cache)");
  auto start = std::chrono::steady_clock::now();
  prt::CachedTransfer result = transferFor(mesh, settings, o.cacheDir, o.threads);
  double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  fmt::print("{}: {} vertices, {} directions each{}\n", o.input, mesh.positions.size(), settings.samples,
             settings.shadows ? "" : " (unshadowed)");
  if (result.fromCache) {
    fmt::print("transfer read from the cache: {}\n", result.file.string());
  } else {
    double rays = static_cast<double>(mesh.positions.size()) * settings.samples;
    fmt::print("baked in {:.2f} s ({:.3g} rays/s), cached: {}\n", seconds, rays / seconds, result.file.string());
  }
}

namespace {

// The report's outputs, checked before the bake: named for their format, writable, and none of
// them an input or the other output.
void checkReportOutputs(const PrtReportOptions& o) {
  for (const auto& [file, option, extension, what] :
       {std::tuple{&o.plotFile, "--plot", ".svg", "plot"}, std::tuple{&o.coloursFile, "--colours", ".ply", "mesh"}}) {
    if (file->empty()) continue;
    requireExtension(*file, extension, option, what);
    requireWritable(*file);
    requireOtherFile(*file, o.input, "the input");
    requireOtherFile(*file, o.exr, "the map (--map)");
  }
  requireOtherFile(o.coloursFile, o.plotFile, "the plot (--plot)");
  if (o.coloursM && o.coloursFile.empty()) throw Error("--colours-m: only with --colours (the basis size of its colours)");
}

// A spectral sky whose sun is past the last sunlit air (prt::sunlitAirLimitDeg): said, since the
// report compares PRT under it all the same.
void warnIfNoSunlitAir(const atmosphere::AtmosphereSky& sky) {
  const double limit = prt::sunlitAirLimitDeg(sky);
  if (sky.sunElevationDeg < limit)
    fmt::print(stderr, "prism: warning: the sun is {:g}° below the horizon, past the {:.1f}° where the last sunlit air "
                       "leaves the sky: what light is left is the extrapolated tail of the atmosphere's multiple "
                       "scattering, which its model does not hold\n", -sky.sunElevationDeg, -limit);
}

// The report's environment (PrtReportOptions says which); flags of another one are refused.
prt::SpectralEnvironment reportEnvironment(const PrtReportOptions& o, const PrtInput* input) {
  const bool sun = o.sunElevationDeg || o.sunAzimuthDeg;
  if (!o.exr.empty() && (o.environment || o.illuminant || sun))
    throw Error("--map: the map is the environment; --environment, --illuminant and the sun's options describe another");
  if (o.environment != "atmosphere" && sun)
    throw Error("--sun-elevation, --sun-azimuth: only with --environment atmosphere");
  if (o.environment == "atmosphere" && o.illuminant)
    throw Error("--illuminant: the atmosphere is lit by its sun, not by an illuminant");
  const prt::PrtSection* section = input ? input->section() : nullptr;
  // The scene's spectral sky: its PRT section's, else its own atmosphere section's, as a PRT
  // section's sky (sunset.json: the report took the F4 sky, and `--environment atmosphere` the
  // defaults' sun at 30°, where the scene's is at 3°); the default environment too where the
  // scene has no PRT section.
  prt::PrtSection atmosphereSky;
  const prt::PrtSection* sceneSky = section && section->sky ? section : nullptr;
  if (const auto* atmosphere = input ? input->scene.techniques.find<atmosphere::AtmosphereSection>() : nullptr;
      atmosphere && !sceneSky) {
    atmosphereSky.sky = prt::PrtSky{.atmosphere = static_cast<const atmosphere::AtmosphereSky&>(*atmosphere),
                                    .sunDisc = true};
    sceneSky = &atmosphereSky;
  }
  if (!section) section = sceneSky;
  if (section && o.exr.empty() && !o.environment && !o.illuminant) {
    if (section->sky) warnIfNoSunlitAir(section->sky->atmosphere);
    // The report has no lights: the spectral sky's sun, the renderer's light, is projected with it.
    prt::SpectralEnvironment environment = prt::sectionEnvironment(*section, rendererRgbToSpectrumTable("srgb"), true);
    environment.name = "the scene's (" + environment.name + ")";
    return environment;
  }
  if (!o.exr.empty()) {
    imaging::FloatImage map = prt::readEnvironmentMap(o.exr);
    std::vector<float> rgb;
    rgb.reserve(3 * map.pixelCount());
    for (int y = 0; y < map.height; ++y)
      for (int x = 0; x < map.width; ++x)
        for (int c = 0; c < 3; ++c) rgb.push_back(map.at(x, y, c));
    harness::ProgressBar bar("RGB → spectrum table (first use)");
    const RgbToSpectrumTable& table =
        rendererRgbToSpectrumTable("srgb", [&bar](std::size_t done, std::size_t total) { bar.update(done, total); });
    return prt::equirectangularEnvironment(o.exr, map.width, map.height, rgb,
                                           [&table](const glm::vec3& c) {
                                             return RgbIlluminantSpectrum(table, colourSpace("srgb"), c).toDense();
                                           });
  }
  const std::string shape = o.environment.value_or("sky");
  const std::string name = o.illuminant.value_or("F4");
  auto light = [&] { return fromOption("--illuminant", [&] { return prt::environmentIlluminant(name); }); };
  if (shape == "sky") return prt::skyGradientEnvironment(name + " sky", light());
  if (shape == "uniform") return prt::uniformEnvironment(name + " uniform", light());
  if (shape != "atmosphere") throw Error("--environment: '" + shape + "' is not sky, uniform or atmosphere");
  // The scene's own sky, when it has one, with the sun moved as asked (its disc, its other keys and
  // the section's rotation kept): the defaults' sky stood in for it, a report at --sun-elevation 15
  // on prt_sky.json putting the sun at 180°, not the scene's 120°, under the same header.
  const bool own = sceneSky != nullptr;
  const double elevation = o.sunElevationDeg.value_or(own ? sceneSky->sky->atmosphere.sunElevationDeg : 30.0);
  const double azimuth = o.sunAzimuthDeg.value_or(own ? sceneSky->sky->atmosphere.sunAzimuthDeg : 180.0);
  if (!(std::abs(elevation) <= 90.0)) throw Error(fmt::format("--sun-elevation: {} is not within -90..90", elevation));
  if (!(std::abs(azimuth) <= 360.0)) throw Error(fmt::format("--sun-azimuth: {} is not within -360..360", azimuth));
  if (own) {
    prt::PrtSection moved = *sceneSky;
    moved.sky->atmosphere.sunElevationDeg = static_cast<float>(elevation);
    moved.sky->atmosphere.sunAzimuthDeg = static_cast<float>(azimuth);
    warnIfNoSunlitAir(moved.sky->atmosphere);
    prt::SpectralEnvironment environment = prt::sectionEnvironment(moved, rendererRgbToSpectrumTable("srgb"), true);
    environment.name = "the scene's " + environment.name;
    return environment;
  }
  prt::PrtSky sky;
  sky.atmosphere.sunElevationDeg = static_cast<float>(elevation);
  sky.atmosphere.sunAzimuthDeg = static_cast<float>(azimuth);
  warnIfNoSunlitAir(sky.atmosphere);
  return prt::skyEnvironment(fmt::format("Prism's spectral sky, sun at {:g}° elevation, {:g}° azimuth", elevation, azimuth),
                             prt::tabulateSky(sky), true, 1.0);
}

}  // namespace

void runPrtReport(const PrtReportOptions& o) {
  if (o.samples) checkSamples(*o.samples);
  checkReportOutputs(o);
  if (o.patchVertices && !o.input.empty())
    throw Error(fmt::format("--patch-vertices {}: only without an input (it shapes the ColorChecker height field), not "
                            "with {}", *o.patchVertices, o.input));
  const int patchVertices = o.patchVertices.value_or(16);
  if (patchVertices < 2 || patchVertices > 256)
    throw Error(fmt::format("--patch-vertices: {} out of range 2..256", patchVertices));
  std::optional<PrtInput> input;
  if (!o.input.empty()) input = loadPrtInput(o.input, true);
  prt::SpectralEnvironment environment = reportEnvironment(o, input ? &*input : nullptr);
  if (!o.rotate.empty()) {  // the environment turned by its SH rotation, not projected again
    if (o.rotate.size() != 4)
      throw Error(fmt::format("--rotate: expected four numbers X,Y,Z,DEGREES, got {}", o.rotate.size()));
    glm::dvec3 axis(o.rotate[0], o.rotate[1], o.rotate[2]);
    if (!(glm::length(axis) > 0.0) || !std::isfinite(glm::length(axis)))
      throw Error("--rotate: the axis X,Y,Z must be non-zero and finite");
    glm::dmat3 rotation(glm::rotate(glm::dmat4(1.0), glm::radians(o.rotate[3]), glm::normalize(axis)));
    environment = prt::rotateEnvironment(environment, rotation);
    environment.name += fmt::format(" turned {}° about ({}, {}, {})", o.rotate[3], axis.x, axis.y, axis.z);
  }
  // ΔE needs a white: a sky whose sun is far enough below the horizon holds no light to compare in.
  if (!(prt::sceneWhite(prt::environmentOnGrid(environment), cie1931Observer()).y() > 0.0))
    throw Error(fmt::format("prt report: {} holds no light (its white's luminance is 0): nothing to compare", environment.name));
  const prt::PrtObject object = input ? input->object : prt::makeColourCheckerObject(patchVertices);
  const prt::BakeSettings bake =
      input ? bakeSettingsFor(*input, o.samples, true) : prt::BakeSettings{o.samples.value_or(prt::BakeSettings{}.samples)};
  // The basis as basisSweep builds it, before the bake, so that --colours-m is checked against the
  // functions it has: one per spectrum of the scene that is not black (a uniform sky's bands 1–4).
  std::vector<Eigen::VectorXd> spectra;
  for (const Spectrum& r : object.reflectances) spectra.push_back(prt::sampleOnGrid(r));
  const prt::SpectralBasis basis(spectra, {prt::termSpectra(environment)});
  const int mMax = std::min(basis.available(), 16);
  const int coloursM = o.coloursM.value_or(std::min(8, mMax));
  if (!o.coloursFile.empty() && (coloursM < 0 || coloursM > mMax))
    throw Error(fmt::format("--colours-m: {} out of range 0..{}", coloursM, mMax));
  prt::CachedTransfer transfer = transferFor(object.mesh, bake, "");
  const Observer& obs = cie1931Observer();
  prt::PrtReport report = prt::basisSweep(object, transfer.transfer, environment, obs);

  if (!o.plotFile.empty()) {
    auto point = [](int m, const prt::DeltaEStatistics& e) {
      return harness::BasisSweepPoint{m, e.mean94, e.max94, e.mean2000, e.max2000};
    };
    std::vector<harness::BasisSweepPoint> points;
    for (const prt::BasisSweepRow& row : report.sweep) points.push_back(point(row.m, row.error));
    writeFileAtomically(o.plotFile, harness::basisSweepPlotSvg(points, point(0, report.rgbError), 1.0,
                                                               "Spectral PRT vs 5 nm sampling: " + environment.name));
  }
  if (!o.coloursFile.empty()) {
    Eigen::MatrixXd grid = prt::environmentOnGrid(environment);
    Eigen::Vector3d white = prt::sceneWhite(grid, obs);
    auto xyz = coloursM == 0 ? prt::shadeReference(object, transfer.transfer, grid, obs)
                             : prt::shadeSpectral(object, transfer.transfer, grid, obs, basis.leading(coloursM));
    auto colours = prt::displayColours(xyz, white, colourSpace("srgb"));
    writeFileAtomically(o.coloursFile, plyText(object, colours));
  }
  if (o.json) {
    nlohmann::json out = {{"environment", environment.name}, {"vertices", report.vertices},
                          {"samples", bake.samples}, {"rgb_prt", statisticsJson(report.rgbError)}};
    for (const prt::BasisSweepRow& row : report.sweep) {
      nlohmann::json r = statisticsJson(row.error);
      r["m"] = row.m;
      r["captured_energy"] = row.capturedEnergy;
      out["spectral"].push_back(r);
    }
    fmt::print("{}\n", out.dump(2));
    return;
  }
  fmt::print("{}, {} vertices, {} directions, environment {}; against 5 nm point sampling "
             "(81 λ) through the same transfer\n",
             o.input.empty() ? "ColorChecker height field" : o.input, report.vertices, bake.samples, environment.name);
  fmt::print("{:>8} {:>10} {:>10} {:>10} {:>10} {:>10}\n", "m", "energy", "mean ΔE94", "max ΔE94", "mean ΔE00", "max ΔE00");
  for (const prt::BasisSweepRow& row : report.sweep)
    fmt::print("{:>8} {:>10.6f} {:>10.4f} {:>10.4f} {:>10.4f} {:>10.4f}\n", row.m, row.capturedEnergy, row.error.mean94,
               row.error.max94, row.error.mean2000, row.error.max2000);
  fmt::print("{:>8} {:>10} {:>10.4f} {:>10.4f} {:>10.4f} {:>10.4f}\n", "RGB-PRT", "", report.rgbError.mean94,
             report.rgbError.max94, report.rgbError.mean2000, report.rgbError.max2000);
}

void runPrtMetamers(const PrtMetamersOptions& o) {
  checkSamples(o.samples);
  if (o.patchVertices < 2 || o.patchVertices > 256)
    throw Error(fmt::format("--patch-vertices: {} out of range 2..256", o.patchVertices));
  Spectrum original = patchOrFileReflectance(o.reflectance, "--reflectance");
  std::vector<prt::SpectralEnvironment> skies;
  for (const std::string& name : o.under)
    skies.push_back(prt::skyGradientEnvironment(name, fromOption("--under", [&] { return prt::environmentIlluminant(name); })));
  const Observer& obs = cie1931Observer();
  prt::Metamer metamer = prt::findMetamer(original, fromOption("--match", [&] { return prt::environmentIlluminant(o.match); }),
                                          fromOption("--target", [&] { return prt::environmentIlluminant(o.target); }), obs);
  prt::PrtObject object = prt::makeColourCheckerObject(o.patchVertices);
  prt::CachedTransfer transfer = transferFor(object.mesh, {o.samples, true}, "");
  std::vector<prt::DeltaEStatistics> halves =
      prt::metamerHalves(object, transfer.transfer, original, metamer.reflectance, skies, obs);
  if (o.json) {
    nlohmann::json out = {{"reflectance", o.reflectance}, {"match", o.match}, {"target", o.target},
                          {"vertices", object.mesh.positions.size()}};
    for (std::size_t i = 0; i < skies.size(); ++i)
      out["halves"][o.under[i]] = {{"mean_de2000", halves[i].mean2000}, {"max_de2000", halves[i].max2000}};
    fmt::print("{}\n", out.dump(2));
    return;
  }
  fmt::print("{} and its metamer (matching under {}, most different under {}) on the ColorChecker height field, "
             "{} vertices, spectral PRT (m ≤ 8):\n",
             o.reflectance, o.match, o.target, object.mesh.positions.size());
  for (std::size_t i = 0; i < skies.size(); ++i)
    fmt::print("  {} sky: halves ΔE00 mean {:.4f}, max {:.4f}\n", o.under[i], halves[i].mean2000, halves[i].max2000);
}

}  // namespace prism::app
