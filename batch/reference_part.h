// A part of a reference render split across processes (`prism reference --tile I/N --samples
// A:B`, one Slurm array task each): some rows and some path indices of one render, in an EXR that
// says which render it belongs to, so that `prism merge` (reference_merge.h) can refuse parts of
// another and put the rest together exactly.
//
// File (imaging/exr_band.h): the render's rows [rowBegin, rowEnd) as the data window of the whole
// image; channels X, Y, Z (R, G, B for a camera): the float mean over the part's paths, as a
// whole render writes it; residual.X… : the mean's rounding residual (reference::ReferenceImage);
// variance.X… : the variance of that mean. String attributes:
//   prism:part          "reference 1" (kind and format version)
//   prism:scene         the scene file as given (for people)
//   prism:sceneHash     FNV-1a 64 of the scene file's bytes, the --set overrides and what they loaded, in hex
//   prism:settings      "key=value …": every setting that shapes the pixels but size, paths, seed
//   prism:seed, prism:samplesPerPixel, prism:observer, prism:ev100
//   prism:samples       "A:B", the path indices of every pixel in the part
//   prism:sampleCount   B − A: how many paths each pixel's mean and variance are over
//   prism:colour        what X, Y, Z / R, G, B mean, as readExr takes it
//   prism:cameraToXyz   a camera's only: its matrix, nine numbers row by row
#pragma once

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <Eigen/Core>

#include "reference/path_tracer.h"

namespace prism::batch {

struct ReferencePartHeader {
  std::string scene;       // the scene file as given
  std::string sceneHash;   // sceneHash() below
  std::string settings;    // settingsText() below
  std::uint32_t seed = 0;
  int width = 0, height = 0, samplesPerPixel = 0;
  std::string observer;    // an observer or a camera (what the channels mean)
  float ev100 = 0.0f;      // the exposure of the merged image's display white and PNG
  reference::ReferenceRegion region;
  // A camera's matrix under the scene's light (render::cameraToXyz), which its merged image is
  // shown and compared through; none for the CIE observers. The caller sets it (partHeader does
  // not: it needs the upsampling table); the scene and the observer, which the identity holds,
  // decide it.
  std::optional<Eigen::Matrix3d> cameraToXyz;

  // What must be equal for two parts to be of one render: (name, value) pairs, in the order a
  // mismatch is reported.
  std::vector<std::pair<std::string, std::string>> identity() const;
  bool operator==(const ReferencePartHeader&) const = default;
};

// FNV-1a 64 of the scene file's bytes, then of each override (after a zero byte), then of what
// `loaded` (that file loaded with those overrides) took from the files it names: its meshes'
// vertices and indices (glTF models), textures' texels, materials' and lights' spectra (CSVs), as
// 16 hex digits; so a model or spectrum changed between two tasks makes their parts foreign. The
// techniques' own files (a PRT map) are not hashed. Error naming the file when it cannot be read.
std::string sceneHash(const std::filesystem::path& scene, const std::vector<std::string>& sets, const Scene& loaded);

// "transport=… max-depth=… filter=… range=MIN,MAX strategy=…".
std::string settingsText(const reference::ReferenceSettings& settings);

// The header of a part of `settings`' render covering `region`.
ReferencePartHeader partHeader(const std::filesystem::path& scene, const std::vector<std::string>& sets,
                               const Scene& loaded, const reference::ReferenceSettings& settings,
                               const reference::ReferenceRegion& region, float ev100);

// Atomically (a task that dies leaves no part). `image` is the region's (renderReference).
void writeReferencePart(const std::filesystem::path& path, const ReferencePartHeader& header,
                        const reference::ReferenceImage& image);

// The header alone (cheap: the pixels are not decoded). Error "PATH: not a part of a reference
// render (…)" naming what is missing or malformed.
ReferencePartHeader readReferencePartHeader(const std::filesystem::path& path);

struct ReferencePart {
  ReferencePartHeader header;
  reference::ReferenceImage image;  // the part's rows
};
// Header and every pixel: a part that reads is complete (a truncated one is an Error).
ReferencePart readReferencePart(const std::filesystem::path& path);

}  // namespace prism::batch
