#include "app/colour_commands.h"

#include <fmt/core.h>
#include <fmt/ranges.h>

#include <Eigen/Core>
#include <cctype>
#include <cmath>
#include <nlohmann/json.hpp>
#include <filesystem>
#include <optional>
#include <sstream>

#include "app/camera_option.h"
#include "app/option_error.h"
#include "core/atomic_file.h"
#include "harness/progress_bar.h"
#include "imaging/spectral_texture_file.h"
#include "spectral/camera_matrix.h"
#include "spectral/colour_difference.h"
#include "spectral/colour_space.h"
#include "spectral/spectrum_csv.h"
#include "core/error.h"
#include "core/file_extension.h"
#include "spectral/illuminant.h"
#include "spectral/observer.h"
#include "spectral/rgb_to_spectrum_cache.h"
#include "spectral/sampling.h"
#include "spectral/sigmoid_fit.h"
#include "spectral/thin_svd.h"
#include "spectral/colour_checker.h"
#include "techniques/prt/metamer.h"

namespace prism::app {
namespace {

using nlohmann::json;

json toJson(const Eigen::Vector3d& v) { return json::array({v.x(), v.y(), v.z()}); }

json toJson(const Eigen::Matrix3d& m) {
  json rows = json::array();
  for (int r = 0; r < 3; ++r) rows.push_back(json::array({m(r, 0), m(r, 1), m(r, 2)}));
  return rows;
}

void requireThree(const std::vector<double>& v, const std::string& what) {
  if (v.size() != 3)
    throw Error(what + ": expected three comma-separated numbers, got " + std::to_string(v.size()));
  for (double x : v)
    if (!std::isfinite(x)) throw Error(what + ": values must be finite");
}

// A camera's values are normalised to its G of the light's white: under a light it does not see
// (led:830:1, past its curves) every value was NaN, printed with exit 0.
void requireCameraSees(const Observer& camera, const Spectrum& light, const std::string& lightName) {
  if (camera.isCamera && !cameraSees(camera, light))
    throw Error(fmt::format("--illuminant: {} does not see {} (its G of the light is below 1e-6 of D65's, for the "
                            "same luminance): no white to normalise to", camera.name, lightName));
}

}  // namespace

void colourXyz(const XyzOptions& o) {
  Spectrum light = fromOption("--illuminant", [&] { return lampSpectrum(o.illuminant); });
  const Observer& obs = *fromOption("--observer", [&] { return &observer(o.observer); });
  requireCameraSees(obs, light, o.illuminant);
  if (!o.reflectanceFile.empty() && !o.rgb.empty())
    throw Error("colour xyz: give --reflectance or --rgb, not both");
  json out = {{"illuminant", o.illuminant}, {"observer", o.observer}};
  Spectrum reflectance = Spectrum::constant(1.0);
  if (!o.reflectanceFile.empty()) {
    reflectance = readSpectrumCsv(o.reflectanceFile, Extrapolation::Clamp, 0.0, 1.0).toDense();
    out["reflectance"] = o.reflectanceFile;
  } else if (!o.rgb.empty()) {
    requireThree(o.rgb, "--rgb");
    for (double channel : o.rgb) {
      if (!(channel >= 0.0 && channel <= 1.0))
        throw Error(fmt::format("--rgb: an albedo's channels lie within [0, 1], got {}", channel));
    }
    const RgbColourSpace& gamut = *fromOption("--gamut", [&] { return &colourSpace(o.gamut); });
    Eigen::Vector3d rgb(o.rgb[0], o.rgb[1], o.rgb[2]);
    if (o.encoded) rgb = gamut.decode(rgb);
    SigmoidFitter fitter(gamut, gamutWhiteIlluminant(gamut), observer("cie1931"));
    SigmoidFit fit = fitter.fit(rgb);
    reflectance = upsampledReflectanceSpectrum(fit.coeffs);
    out["rgb"] = {{"gamut", o.gamut}, {"linear", toJson(rgb)}};
    out["upsampling"] = {{"model", "jakob-hanika-2019"},
                         {"coefficients", {fit.coeffs.x, fit.coeffs.y, fit.coeffs.z}},
                         {"fitDeltaE76", fit.deltaE76}};
  }
  Eigen::Vector3d value = reflectanceTristimulus(obs, reflectance, light);
  Eigen::Vector3d white = whiteTristimulus(obs, light);
  const char* key = obs.isCamera ? "cameraRgb" : "xyz";
  out[key] = toJson(value);
  out["whiteY"] = 1.0;
  if (!obs.isCamera) {
    // Black (below a millionth of the white) has no chromaticity: its xy was the ratio of two
    // roundings (0.699, 0.301 for --rgb 0,0,0).
    if (value.sum() > 1e-6 * white.y()) {
      Chromaticity xy = xyzToXy(value);
      out["xy"] = {xy.x, xy.y};
    } else {
      out["xy"] = nullptr;
    }
    out["lab"] = toJson(xyzToLab(value, white));
  }
  if (o.sample) {
    if (o.rangeNm.size() != 2) throw Error("--range: expected MIN,MAX in nm");
    SamplingSettings settings{o.wavelengthCount, o.rangeNm[0], o.rangeNm[1],
                              fromOption("--strategy", [&] { return samplingStrategyFromName(o.strategy); })};
    fromOption("--wavelengths", [&] { validateWavelengthCount(settings.count); });
    validate(settings);
    // Lights follows the illuminant, the only light here; Optimised is fitted under it alone, on
    // the standard training set (sRGB's gamut), with a progress bar when not cached.
    std::optional<harness::ProgressBar> bar;
    const WavelengthSampler sampler =
        settings.strategy == SamplingStrategy::Optimised
            ? WavelengthSampler(settings, cachedFitWavelengths({{light},
                                                                standardTrainingReflectances(rendererRgbToSpectrumTable("srgb")),
                                                                settings.count, settings.minNm, settings.maxNm},
                                                               obs,
                                                               [&bar](std::size_t done, std::size_t total) {
                                                                 if (!bar) bar.emplace("fitting wavelengths");
                                                                 bar->update(done, total);
                                                               }))
            : WavelengthSampler(settings, obs, light);
    std::vector<SampledWavelengths> batches = sampler.sample(o.seed);
    std::vector<IntegrationMatrix> matrices = sampler.matrices(batches, obs);
    Eigen::Vector3d sampled = Eigen::Vector3d::Zero();
    for (std::size_t b = 0; b < batches.size(); ++b) {
      Eigen::Vector4d radiance;
      for (std::size_t j = 0; j < 4; ++j)
        radiance[static_cast<Eigen::Index>(j)] =
            reflectance.at(batches[b].lambdaNm[j]) * light.at(batches[b].lambdaNm[j]);
      sampled += matrices[b] * radiance;
    }
    const double whiteY = (light * obs.curves[1]).integral();
    sampled /= whiteY;
    // What a frame within the range integrates, whatever its strategy: the light within it
    // (lightWithinRange) at 1 nm, on the same scale (the whole light's white, Y = 1), in CIELAB
    // against the range's own white, as `wavelengths optimise` measures. Against the whole band
    // every strategy read the range's cut: ΔE00 34 for 500–600 nm, even at 400 wavelengths.
    const Spectrum banded = lightWithinRange(light, settings.minNm, settings.maxNm);
    const Eigen::Vector3d truth = obs.integrate(banded * reflectance) / whiteY;
    const Eigen::Vector3d bandWhite = fitWhite(banded, obs) / whiteY;
    json s = {{"count", o.wavelengthCount}, {"strategy", o.strategy}, {"rangeNm", {o.rangeNm[0], o.rangeNm[1]}},
              {"value", toJson(sampled)}, {"integral", toJson(truth)}};
    if (!obs.isCamera) s["deltaE2000"] = deltaE(xyzToLab(sampled, bandWhite), xyzToLab(truth, bandWhite));
    out["sampled"] = s;
  }
  if (o.json) {
    fmt::print("{}\n", out.dump(2));
    return;
  }
  fmt::print("{} {:.6f} {:.6f} {:.6f}   (perfect white: {} = 1 under {})\n", obs.isCamera ? "camera RGB" : "XYZ",
             value.x(), value.y(), value.z(), obs.isCamera ? "G" : "Y", o.illuminant);
  if (!obs.isCamera) {
    if (out["xy"].is_null()) fmt::print("xy  none (black)\n");
    else fmt::print("xy  {:.6f} {:.6f}\n", out["xy"][0].get<double>(), out["xy"][1].get<double>());
    fmt::print("Lab {:.4f} {:.4f} {:.4f}\n", out["lab"][0].get<double>(), out["lab"][1].get<double>(),
               out["lab"][2].get<double>());
  }
  if (out.contains("sampled")) {
    fmt::print("sampled ({} wavelengths, {}): {:.6f} {:.6f} {:.6f}", o.wavelengthCount, o.strategy,
               out["sampled"]["value"][0].get<double>(), out["sampled"]["value"][1].get<double>(),
               out["sampled"]["value"][2].get<double>());
    if (out["sampled"].contains("deltaE2000"))
      fmt::print("   ΔE00 vs 1 nm: {:.4f}", out["sampled"]["deltaE2000"].get<double>());
    fmt::print("\n");
    if (o.rangeNm[0] > kLambdaMinNm || o.rangeNm[1] < kLambdaMaxNm)
      fmt::print("1 nm within {:g}–{:g} nm: {:.6f} {:.6f} {:.6f}   (what the sampled value is measured against)\n",
                 o.rangeNm[0], o.rangeNm[1], out["sampled"]["integral"][0].get<double>(),
                 out["sampled"]["integral"][1].get<double>(), out["sampled"]["integral"][2].get<double>());
  }
  if (out.contains("upsampling")) {
    const json& c = out["upsampling"]["coefficients"];
    fmt::print("sigmoid coefficients {:.6g} {:.6g} {:.6g} (fit ΔE76 {:.2g})\n", c[0].get<double>(),
               c[1].get<double>(), c[2].get<double>(), out["upsampling"]["fitDeltaE76"].get<double>());
  }
}

void colourDeltaE(const DeltaEOptions& o) {
  PRISM_CHECK(o.labs.size() == 2);  // main.cpp refuses any other count as a malformed command line
  for (const std::vector<double>& lab : o.labs) {
    requireThree(lab, "--lab");
    if (lab[0] < 0.0) throw Error(fmt::format("--lab: L* {:g} is negative", lab[0]));
  }
  DeltaEFormula formula = deltaEFormulaFromName(o.formula);
  Eigen::Vector3d a(o.labs[0][0], o.labs[0][1], o.labs[0][2]);
  Eigen::Vector3d b(o.labs[1][0], o.labs[1][1], o.labs[1][2]);
  double d = deltaE(a, b, formula);
  if (!std::isfinite(d)) throw Error(fmt::format("colour delta-e: the difference of these colours is {}", d));
  if (o.json)
    fmt::print("{}\n", json{{"formula", o.formula}, {"deltaE", d}}.dump(2));
  else
    fmt::print("{:.4f}\n", d);
}

void colourCct(const CctOptions& o) {
  if (o.stepNm < 1 || o.stepNm > 10) throw Error("--step must be within 1–10 nm");
  if (!o.output.empty()) requireExtension(o.output, ".csv", "-o", "spectrum");
  Spectrum s = daylight(o.cctK);
  std::ostringstream csv;
  csv << "wavelength_nm,value\n";
  // The range's end too, where the step does not reach it (7 nm ended at 829).
  for (int l = kLambdaMinNm; l < kLambdaMaxNm + o.stepNm; l += o.stepNm) {
    const int at = std::min(l, kLambdaMaxNm);
    csv << at << ',' << fmt::format("{:.6g}", s.at(at)) << '\n';
  }
  if (o.output.empty()) {
    fmt::print("{}", csv.str());
  } else {
    writeFileAtomically(o.output, csv.str());
    fmt::print("wrote {}\n", o.output);
  }
}

void colourConvert(const ConvertOptions& o) {
  requireThree(o.values, "colour convert");
  Eigen::Vector3d in(o.values[0], o.values[1], o.values[2]);
  // "none", as `chart` takes it: the same XYZ in the other space, its white left as it was.
  const std::string adaptationName = o.adaptation.value_or("bradford");
  std::optional<Adaptation> adaptation;
  if (adaptationName != "none") {
    try {
      adaptation = adaptationFromName(adaptationName);
    } catch (const Error&) {
      throw Error(fmt::format("--adaptation: unknown chromatic adaptation '{}' (known: bradford, cat02, von-kries, none)",
                              adaptationName));
    }
  }
  // xyz or an RGB space; an unknown name's error lists xyz too, which colourSpace's cannot know.
  auto space = [](const std::string& name, const char* option) -> const RgbColourSpace* {
    if (name == "xyz") return nullptr;
    try {
      return &colourSpace(name);
    } catch (const Error& e) {
      throw Error(fmt::format("{}: {} (or xyz)", option, e.what()));
    }
  };
  const RgbColourSpace* from = space(o.from, "--from");
  const RgbColourSpace* to = space(o.to, "--to");
  // Refused as --seed is under a strategy that draws nothing: it was taken and did nothing.
  if (o.adaptation && !(from && to))
    throw Error("--adaptation: a conversion to or from xyz adapts nothing (XYZ carries no white); give it between "
                "two RGB spaces");
  // XYZ carries no white: adaptation happens only between two RGB spaces' whites.
  Eigen::Matrix3d m = Eigen::Matrix3d::Identity();
  if (from && to) m = adaptation ? rgbToRgb(*from, *to, *adaptation) : Eigen::Matrix3d(to->xyzToRgb * from->rgbToXyz);
  else if (from) m = from->rgbToXyz;
  else if (to) m = to->xyzToRgb;
  // The transfer functions mirrored about 0, as extended-range sRGB does: a negative or over-range
  // value converts and converts back instead of being clamped to 0 (it read as in gamut).
  const auto mirrored = [](const Eigen::Vector3d& v, auto&& transfer) {
    Eigen::Vector3d out = transfer(Eigen::Vector3d(v.cwiseAbs()));
    for (int c = 0; c < 3; ++c) out[c] = std::copysign(out[c], v[c]);
    return out;
  };
  const Eigen::Vector3d decoded =
      from && !o.linear ? mirrored(in, [from](const Eigen::Vector3d& x) { return from->decode(x); }) : in;
  Eigen::Vector3d linear = m * decoded;
  Eigen::Vector3d value = to && !o.linear ? mirrored(linear, [to](const Eigen::Vector3d& x) { return to->encode(x); }) : linear;
  // Out of gamut: a component below 0, outside the primaries' triangle, and for a display space (a
  // transfer curve: srgb, display-p3, rec2020) one above 1 too, past what it shows; scene-linear
  // ACES takes any light. Within a tenth of a per cent, of the colour's own scale below 0 (a hue
  // does not depend on how bright it is) and of 1 above: D65's white as the CIE tables integrate
  // it (x, y 0.31272, 0.32903, not sRGB's 0.3127, 0.3290) read linear 1.00016 in sRGB, said out
  // of gamut.
  constexpr double kTolerance = 1e-3;
  const bool inGamut = !to || ((linear.array() >= -kTolerance * linear.cwiseAbs().maxCoeff()).all() &&
                               (to->transfer == Transfer::Linear || (linear.array() <= 1.0 + kTolerance).all()));
  if (o.json) {
    fmt::print("{}\n", json{{"from", o.from}, {"to", o.to}, {"linear", toJson(linear)},
                            {"value", toJson(value)}, {"inGamut", inGamut}}
                           .dump(2));
    return;
  }
  fmt::print("{:.6f} {:.6f} {:.6f}{}\n", value.x(), value.y(), value.z(),
             inGamut ? "" : "   (out of gamut; linear " + fmt::format("{:.6f} {:.6f} {:.6f}", linear.x(), linear.y(), linear.z()) + ")");
}

void colourCameraMatrix(const CameraMatrixOptions& o) {
  const Observer& camera = cameraOption(o.camera);
  const Spectrum light = fromOption("--illuminant", [&] { return lampSpectrum(o.illuminant); });
  requireCameraSees(camera, light, o.illuminant);
  CameraMatrixFit fit = fitCameraToXyz(camera, light, observer("cie1931"));
  warnIfIllPosed(fit.chartConditioning, o.illuminant, o.camera);
  if (o.json) {
    fmt::print("{}\n", json{{"camera", o.camera}, {"illuminant", o.illuminant},
                            {"cameraToXyz", toJson(fit.cameraToXyz)},
                            {"meanDeltaE2000", fit.meanDeltaE2000}, {"maxDeltaE2000", fit.maxDeltaE2000},
                            {"chartConditioning", fit.chartConditioning}}
                           .dump(2));
    return;
  }
  for (int r = 0; r < 3; ++r)
    fmt::print("{:10.6f} {:10.6f} {:10.6f}\n", fit.cameraToXyz(r, 0), fit.cameraToXyz(r, 1),
               fit.cameraToXyz(r, 2));
  fmt::print("ColorChecker under {}: mean ΔE00 {:.3f}, max {:.3f}; conditioning {:.2g} (smallest / largest singular "
             "value of its camera colours)\n", o.illuminant, fit.meanDeltaE2000, fit.maxDeltaE2000, fit.chartConditioning);
}

void colourList(const std::string& what, bool jsonOut) {
  json out = json::array();
  if (what == "illuminants") {
    for (const IlluminantInfo& i : listIlluminants())
      out.push_back({{"name", i.name}, {"normalisation", i.normalisation}});
  } else if (what == "observers") {
    for (const std::string& n : listObservers()) out.push_back(n);
  } else if (what == "cameras") {
    for (const std::string& n : listCameras()) out.push_back(n);
  } else if (what == "spaces") {
    for (const std::string& n : listColourSpaces()) out.push_back(n);
  } else {
    throw Error(what.empty() ? "colour list: say which list: illuminants, observers, cameras or spaces"
                             : "colour list: unknown list '" + what + "' (illuminants, observers, cameras, spaces)");
  }
  if (jsonOut) {
    fmt::print("{}\n", out.dump(2));
    return;
  }
  for (const json& item : out)
    if (item.is_object())
      fmt::print("{:<34} {}\n", item["name"].get<std::string>(), item["normalisation"].get<std::string>());
    else
      fmt::print("{}\n", item.get<std::string>());
}

Spectrum patchOrFileReflectance(const std::string& text, const std::string& option) {
  for (const ColourCheckerPatch& p : colourChecker())
    if (p.name == text) return p.reflectance;
  if (std::filesystem::is_regular_file(text)) return readSpectrumCsv(text, Extrapolation::Clamp, 0.0, 1.0).toDense();
  // A name as a user types it: 'Dark Skin', light_skin (refused, listing nothing).
  auto loose = [](std::string name) {
    for (char& c : name) c = c == '_' || c == '-' ? ' ' : static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return name;
  };
  std::vector<std::string> names;
  for (const ColourCheckerPatch& p : colourChecker()) {
    const std::string name = loose(p.name);  // 'white 9.5 (.05 D)' also as white_9.5
    if (name == loose(text) || name.substr(0, name.find(" (")) == loose(text)) return p.reflectance;
    names.push_back(p.name);
  }
  throw Error(fmt::format("{}: '{}' is neither a ColorChecker patch name nor a file (patches: {})", option, text,
                          fmt::join(names, ", ")));
}

void colourSpectralTexture(const SpectralTextureOptions& o) {
  if (o.cell < 1 || o.cell > 256) throw Error("colour spectral-texture: --cell must be 1 to 256, got " + std::to_string(o.cell));
  if (o.basis < 0 || o.basis > 24) throw Error("colour spectral-texture: --basis must be 0 to 24, got " + std::to_string(o.basis));
  requireExtension(o.output, ".exr", "", "spectral texture");
  requireWritable(o.output);
  SpectralTexture t;
  t.width = 6 * o.cell;
  t.height = 4 * o.cell;
  for (int i = 0; i <= 80; ++i) t.wavelengthsNm.push_back(380.0 + 5.0 * i);
  Eigen::MatrixXd spectra(81, 24);  // the patches on the wavelengths, in chart order
  for (std::size_t p = 0; p < 24; ++p)
    for (int i = 0; i <= 80; ++i) spectra(i, static_cast<Eigen::Index>(p)) = colourChecker()[p].reflectance.at(t.wavelengthsNm[static_cast<std::size_t>(i)]);
  Eigen::MatrixXd patchValues = spectra;  // per patch its k values
  t.sampled = o.basis == 0;
  t.basis = Eigen::MatrixXd::Identity(81, 81);
  double worst = 0.0;
  if (!t.sampled) {
    t.basis = leftSingularVectors(spectra).vectors.leftCols(o.basis);
    patchValues = t.basis.transpose() * spectra;
    Eigen::MatrixXd reconstructed = t.basis * patchValues;
    worst = (reconstructed - spectra).cwiseAbs().maxCoeff();
    if (reconstructed.minCoeff() < -0.01 || reconstructed.maxCoeff() > 1.01)
      throw Error(fmt::format("colour spectral-texture: with {} function{} the patches' reflectances reach [{:.3f}, "
                              "{:.3f}], outside [0, 1] ± 0.01: use more", o.basis, o.basis == 1 ? "" : "s",
                              reconstructed.minCoeff(), reconstructed.maxCoeff()));
  }
  for (int y = 0; y < t.height; ++y) {
    for (int x = 0; x < t.width; ++x) {
      const Eigen::Index patch = (y / o.cell) * 6 + x / o.cell;
      for (Eigen::Index j = 0; j < patchValues.rows(); ++j) t.coefficients.push_back(static_cast<float>(patchValues(j, patch)));
    }
  }
  imaging::writeSpectralTexture(o.output, t);
  if (t.sampled) {
    fmt::print("wrote {}: the ColorChecker, {} × {} texels, samples at 81 wavelengths (380–780 nm, 5 nm)\n", o.output,
               t.width, t.height);
  } else {
    fmt::print("wrote {}: the ColorChecker, {} × {} texels, {} basis function{} (largest reconstruction error {:.2g})\n",
               o.output, t.width, t.height, o.basis, o.basis == 1 ? "" : "s", worst);
  }
}

void colourMetamer(const MetamerOptions& o) {
  if (!o.output.empty()) {
    requireExtension(o.output, ".csv", "-o", "metamer");  // -o m.png wrote CSV text into a .png
    requireWritable(o.output);
    requireOtherFile(o.output, o.reflectance, "the reflectance (--reflectance)");
  }
  const Observer& obs = *fromOption("--observer", [&] { return &observer(o.observer); });
  // The metamer is matched and measured in CIELAB, which a camera's raw RGB has no meaning in.
  if (obs.isCamera) throw Error(fmt::format("--observer: '{}' is a camera; metamers are matched in CIELAB "
                                            "(cie1931 or cie1964)", o.observer));
  Spectrum original = patchOrFileReflectance(o.reflectance, "--reflectance");
  std::vector<std::pair<std::string, Spectrum>> lights;
  for (const std::string& name : o.under) lights.emplace_back(name, fromOption("--under", [&] { return lampSpectrum(name); }));
  prt::Metamer m = prt::findMetamer(original, fromOption("--match", [&] { return lampSpectrum(o.match); }),
                                    fromOption("--target", [&] { return lampSpectrum(o.target); }), obs);
  json out = {{"reflectance", o.reflectance}, {"match", o.match}, {"target", o.target}};
  for (const auto& [name, spd] : lights) out["delta_e2000"][name] = prt::reflectanceDeltaE2000(original, m.reflectance, spd, obs);
  if (!o.output.empty()) {
    std::string csv = "wavelength_nm,reflectance\n";
    for (int i = 0; i < kSpectrumSamples; ++i) csv += fmt::format("{},{:.6f}\n", kLambdaMinNm + i, m.reflectance[i]);
    writeFileAtomically(o.output, csv);
    out["output"] = o.output;
  }
  if (o.json) {
    out["metamer_5nm"] = std::vector<double>(m.gridValues.data(), m.gridValues.data() + m.gridValues.size());
    fmt::print("{}\n", out.dump(2));
    return;
  }
  fmt::print("metamer of {} under {} (maximising the difference under {}), 380–780 nm at 5 nm:\n", o.reflectance,
             o.match, o.target);
  for (Eigen::Index i = 0; i < m.gridValues.size(); ++i)
    fmt::print("{:.4f}{}", m.gridValues[i], (i + 1) % 9 == 0 || i + 1 == m.gridValues.size() ? "\n" : " ");
  for (const auto& [name, spd] : lights)
    fmt::print("ΔE00 under {}: {:.4f}\n", name, out["delta_e2000"][name].get<double>());
}

}  // namespace prism::app
