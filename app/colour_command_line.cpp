#include "app/colour_command_line.h"

#include <fmt/format.h>

#include <memory>
#include <string>
#include <vector>

#include "app/camera_option.h"
#include "app/cli_settings.h"
#include "app/colour_commands.h"
#include "app/option_lists.h"
#include "core/error.h"

namespace prism::app {
namespace {

// What the subcommands' options fill, alive as long as the callbacks that read it.
struct ColourCommandOptions {
  XyzOptions xyz;
  std::string rgbText, xyzCamera, rangeText;
  DeltaEOptions de;
  std::vector<std::string> labTexts;
  CctOptions cct;
  ConvertOptions conv;
  std::string convText;
  CameraMatrixOptions cam;
  std::string listWhat;
  bool listJson = false;
  MetamerOptions metamer;
  std::string metamerUnder;
  SpectralTextureOptions spectralTexture;
};

}  // namespace

void addColourCommands(CLI::App& app) {
  auto o = std::make_shared<ColourCommandOptions>();
  auto* colour = app.add_subcommand("colour", "Colorimetry: XYZ of spectra, colour differences, conversions");
  colour->require_subcommand(1);

  auto* xyzCmd = colour->add_subcommand("xyz", "XYZ (or camera RGB) of a reflectance or RGB albedo under an illuminant");
  xyzCmd->add_option("--illuminant", o->xyz.illuminant, "illuminant name (see `colour list illuminants`) or a spectrum file (.csv)")->capture_default_str();
  auto* xyzObserverOpt =
      xyzCmd->add_option("--observer", o->xyz.observer, "cie1931, cie1964 or a camera")->capture_default_str();
  // As render, reference and the other commands name a camera (it failed: "arguments were not expected").
  xyzCmd->add_option("--camera", o->xyzCamera, "a camera as the observer (raw camera RGB)")
      ->excludes(xyzObserverOpt)
      ->check(cameraName());
  auto* reflOpt = xyzCmd->add_option("--reflectance", o->xyz.reflectanceFile, "spectral CSV: wavelength_nm,value");
  auto* xyzRgbOpt =
      xyzCmd->add_option("--rgb", o->rgbText, "r,g,b albedo, upsampled with a Jakob–Hanika fit")->excludes(reflOpt);
  // --gamut and --encoded describe --rgb: without it they were ignored.
  xyzCmd->add_option("--gamut", o->xyz.gamut, "colour space of --rgb")->capture_default_str()->needs(xyzRgbOpt);
  xyzCmd->add_flag("--encoded", o->xyz.encoded, "--rgb is transfer-encoded (e.g. 8-bit sRGB / 255), not linear")
      ->needs(xyzRgbOpt);
  auto* wavelengthsOpt = xyzCmd->add_option("--wavelengths", o->xyz.wavelengthCount,
                     "also estimate from N sampled wavelengths (a multiple of 4, 4–1000)");
  xyzCmd->add_option("--range", o->rangeText, "MIN,MAX nm of the sampled wavelengths (within 360–830)");
  auto* xyzStrategyOpt = xyzCmd->add_option("--strategy", o->xyz.strategy,
                     "uniform, stratified, rotated, importance (the observer's response), lights (the "
                     "illuminant × that response) or optimised (fitted for the illuminant)")->capture_default_str();
  auto* xyzSeedOpt = xyzCmd->add_option("--seed", o->xyz.seed, "seed of stratified, rotated, importance and lights sampling");
  xyzCmd->add_flag("--json", o->xyz.json, "JSON output");

  auto* deCmd = colour->add_subcommand("delta-e", "colour difference of two CIELAB colours");
  deCmd->add_option("--lab", o->labTexts, "L,a,b (give twice)")->required();
  deCmd->add_option("--formula", o->de.formula, "2000, 94 or 76")->capture_default_str();
  deCmd->add_flag("--json", o->de.json, "JSON output");

  auto* cctCmd = colour->add_subcommand("cct", "CIE daylight SPD at a correlated colour temperature, as CSV");
  cctCmd->add_option("kelvin", o->cct.cctK, "4000–25000 K")->required();
  cctCmd->add_option("--step", o->cct.stepNm, "wavelength step in nm (1–10)")->capture_default_str();
  cctCmd->add_option("-o,--output", o->cct.output, "CSV file to write (default: stdout)");

  auto* convCmd = colour->add_subcommand("convert", "convert a colour between RGB spaces (or xyz)");
  convCmd->add_option("--from", o->conv.from, "srgb, display-p3, rec2020, acescg, aces2065-1, xyz")->required();
  convCmd->add_option("--to", o->conv.to, "same choices as --from")->required();
  convCmd->add_option("values", o->convText, "r,g,b (encoded unless --linear) or X,Y,Z")->required();
  convCmd->add_option("--adaptation", o->conv.adaptation, "bradford (the default), cat02, von-kries or none: between two RGB spaces' whites (XYZ has none: refused with xyz, which it would not adapt)");
  convCmd->add_flag("--linear", o->conv.linear, "values are linear, not transfer-encoded");
  convCmd->add_flag("--json", o->conv.json, "JSON output");

  auto* camCmd = colour->add_subcommand("camera-matrix", "least-squares camera RGB → XYZ matrix on the ColorChecker");
  camCmd->add_option("--camera", o->cam.camera, "camera name (see `colour list cameras`)")
      ->required()
      ->check(cameraName());
  camCmd->add_option("--illuminant", o->cam.illuminant, "illuminant of the fit (a name or a .csv spectrum)")->capture_default_str();
  camCmd->add_flag("--json", o->cam.json, "JSON output");

  auto* listCmd = colour->add_subcommand("list", "list known names");
  // Not required by CLI11, whose "what is required" names no list: colourList says which there are.
  listCmd->add_option("what", o->listWhat, "illuminants, observers, cameras or spaces");
  listCmd->add_flag("--json", o->listJson, "JSON output");

  auto* metamerCmd = colour->add_subcommand("metamer", "a metamer: the same colour under one illuminant, as different as possible under another");
  metamerCmd->add_option("--reflectance", o->metamer.reflectance, "a ColorChecker patch name or a spectral CSV")->required();
  metamerCmd->add_option("--match", o->metamer.match, "illuminant under which the colours match (a name or a .csv spectrum)")->capture_default_str();
  metamerCmd->add_option("--target", o->metamer.target, "illuminant under which they differ most (a name or a .csv spectrum)")->capture_default_str();
  o->metamerUnder = fmt::format("{}", fmt::join(o->metamer.under, ","));
  auto* metamerUnderOpt = metamerCmd->add_option("--under", o->metamerUnder, "illuminants to report ΔE00 under, comma-separated (names or .csv spectra)")
                              ->capture_default_str();
  metamerCmd->add_option("--observer", o->metamer.observer, "cie1931 or cie1964")->capture_default_str();
  metamerCmd->add_option("-o,--output", o->metamer.output, "CSV of the metamer to write");
  metamerCmd->add_flag("--json", o->metamer.json, "JSON output");

  auto* spectralTextureCmd = colour->add_subcommand("spectral-texture", "the ColorChecker as a spectral texture (docs/spectral-texture.md)");
  spectralTextureCmd->add_option("output", o->spectralTexture.output, "the .exr to write")->required();
  spectralTextureCmd->add_option("--cell", o->spectralTexture.cell, "texels per patch side")->capture_default_str();
  spectralTextureCmd->add_option("--basis", o->spectralTexture.basis, "0: samples at 5 nm; k: k SVD basis functions")->capture_default_str();


  xyzCmd->callback([o, wavelengthsOpt, xyzStrategyOpt, xyzSeedOpt] {
    XyzOptions& xyz = o->xyz;
    if (!o->rgbText.empty()) xyz.rgb = parseNumbers(o->rgbText, "--rgb");
    if (!o->xyzCamera.empty()) {
      cameraOption(o->xyzCamera);  // a camera, not a CIE observer by another name
      xyz.observer = o->xyzCamera;
    }
    if (!o->rangeText.empty()) xyz.rangeNm = parseNumbers(o->rangeText, "--range");
    // Any sampling option asks for the sampled estimate (16 wavelengths unless --wavelengths).
    xyz.sample = wavelengthsOpt->count() > 0 || !o->rangeText.empty() || xyzStrategyOpt->count() > 0 ||
                 xyzSeedOpt->count() > 0;
    if (xyzSeedOpt->count() > 0 && (xyz.strategy == "uniform" || xyz.strategy == "optimised"))
      throw Error(fmt::format("--seed: the {} strategy draws no random numbers (stratified, rotated, importance "
                              "and lights do)", xyz.strategy));
    colourXyz(xyz);
  });
  deCmd->callback([o] {
    // A malformed command line (exit 2), as a missing --lab is.
    if (o->labTexts.size() != 2) throw CLI::ValidationError("--lab", "give it exactly twice, one colour each");
    for (const std::string& t : o->labTexts) o->de.labs.push_back(parseNumbers(t, "--lab"));
    colourDeltaE(o->de);
  });
  cctCmd->callback([o] { colourCct(o->cct); });
  convCmd->callback([o] {
    o->conv.values = parseNumbers(o->convText, "colour convert");
    colourConvert(o->conv);
  });
  camCmd->callback([o] { colourCameraMatrix(o->cam); });
  listCmd->callback([o] { colourList(o->listWhat, o->listJson); });
  metamerCmd->callback([o, metamerUnderOpt] {
    if (metamerUnderOpt->count() > 0) o->metamer.under = parseNames(o->metamerUnder, "--under");
    colourMetamer(o->metamer);
  });
  spectralTextureCmd->callback([o] { colourSpectralTexture(o->spectralTexture); });
}

}  // namespace prism::app
