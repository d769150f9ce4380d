// Textured reflectance for PRT objects: the paper's m-layer texture of R̂_j,c (three channels, x̄,
// ȳ, z̄, per basis function), made per texel from a material's reflectance texture — a spectral
// texture (docs/spectral-texture.md) or an RGB base colour texture × base colour, upsampled per
// texel by the Jakob–Hanika table (the albedo intent, as the deferred pipeline and the reference
// upsample it).
//
// R̂ is linear in the reflectance, so each projection is a matrix W (3·basisCount × 81, row 3j + c)
// applied to the texel's spectrum on the 5 nm grid. W is found by putting the grid's 81 hat
// spectra through the mode's own projection (gridReflectanceMaps), so that a texture and a
// material's measured reflectance are one formula: a texel holding a material's spectrum has its
// R̂. Linear also means that filtering R̂ (bilinear, mipmaps) filters the reflectance.
#pragma once

#include <cstdint>
#include <functional>
#include <memory>
#include <vector>

#include <Eigen/Core>
#include <glm/glm.hpp>

#include "spectral/rgb_to_spectrum_table.h"
#include "spectral/spectral_texture.h"
#include "techniques/prt/prt_evaluation.h"

namespace prism::prt {

// An 8-bit RGBA image (row 0 at the top) as a material's base colour texture: linear RGB albedo
// = base colour × texel (sRGB-decoded when `srgb`).
struct PrtRgbTexels {
  int width = 0, height = 0;
  std::vector<std::uint8_t> rgba;
  bool srgb = true;
  glm::vec3 baseColour{1.0f};
};

// The reflectance texture of one PRT material, either kind; texels on the 5 nm grid.
class PrtTextureSource {
 public:
  explicit PrtTextureSource(std::shared_ptr<const SpectralTexture> spectral);
  // `table` upsamples the albedos (the scene's colour space's); it must outlive the source.
  PrtTextureSource(PrtRgbTexels rgb, const RgbToSpectrumTable& table);

  int width() const;
  int height() const;
  // Texel (x, y)'s reflectance at the 81 grid wavelengths.
  Eigen::VectorXd gridReflectance(int x, int y) const;
  // Up to 16 × 16 texels on a regular lattice, each distinct spectrum once: what the texture
  // adds to the spectral basis's SVD (prt_spectra.h) besides the materials' reflectances.
  std::vector<Eigen::VectorXd> representativeSpectra() const;
  // An RGB source's texel (x, y) as one number, its 8-bit R, G, B: equal keys, equal reflectance.
  std::uint32_t rgbKey(int x, int y) const;

  const SpectralTexture* spectral() const { return mSpectral.get(); }

 private:
  std::shared_ptr<const SpectralTexture> mSpectral;
  Eigen::MatrixXd mGridBasis;  // spectral: the basis on the grid (81 × k)
  PrtRgbTexels mRgb;
  const RgbToSpectrumTable* mTable = nullptr;
};

// Each projection's W (3·basisCount × 81): `project` (the mode's projection of a list of
// reflectances: spectral, RGB-PRT or the 5 nm reference's chunks) applied to the grid's hats.
std::vector<Eigen::MatrixXd> gridReflectanceMaps(
    const std::function<std::vector<PrtProjection>(const std::vector<Spectrum>&)>& project);

// A float as the GPU's RGBA16F texel stores it (round to nearest half).
float halfRounded(float value);

// R̂ of a source's texels under one map, as the GPU samples them: every value rounded to half.
class PrtTexelProjector {
 public:
  PrtTexelProjector(const PrtTextureSource& source, const Eigen::MatrixXd& map);
  int basisCount() const { return mBasisCount; }
  // Texel (x, y)'s R̂_j (j < basisCount; the rest 0), half-rounded.
  shared::PrtReflectance texel(int x, int y) const;
  // Every texel as the texture's layers: j-major, rows top first, RGBA half floats (A = 0), for
  // GL_RGBA16F; over `threads` (0: all), the same bits for any count.
  std::vector<std::uint16_t> layers(unsigned threads = 0) const;

 private:
  const PrtTextureSource& mSource;
  Eigen::MatrixXd mMap;         // W, or W·G·B for a spectral texture (then applied to the texel's k values)
  int mBasisCount = 0;
};

}  // namespace prism::prt
