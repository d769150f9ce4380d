// A texture of reflectance spectra, as Prism's spectral texture files hold one
// (docs/spectral-texture.md; imaging/spectral_texture_file.h reads and writes them). Each texel
// carries k values c; its reflectance is r(λ) = Σ_j c_j b_j(λ), the k functions b_j tabulated at n
// wavelengths, linear between them and constant beyond the ends (as a measured reflectance: the
// last value is the best estimate of the next). The file's two forms are two bases: "samples"
// (b_j the n hats, c the reflectance at the wavelengths, k = n) and "coefficients" (k functions
// of the file's own, e.g. from an SVD, k ≤ n).
#pragma once

#include <cstddef>
#include <string>
#include <utility>
#include <vector>

#include <Eigen/Core>
#include <glm/glm.hpp>

namespace prism {

struct SpectralTexture {
  std::string source;                 // the file, for messages
  int width = 0, height = 0;
  std::vector<double> wavelengthsNm;  // n, strictly increasing
  Eigen::MatrixXd basis;              // n × k: b_j(λ_i) in column j
  bool sampled = true;                // the samples form: basis is the n × n identity
  std::vector<float> coefficients;    // width·height·k, texel by texel, row 0 at the top

  int channels() const { return static_cast<int>(basis.cols()); }
  // Texel (x, y)'s k values (x < width, y < height, row 0 at the top).
  Eigen::Map<const Eigen::VectorXf> texel(int x, int y) const;
};

// The basis at each wavelength of `lambdasNm` (size × k): linear between the texture's
// wavelengths, constant beyond its ends.
Eigen::MatrixXd basisAt(const SpectralTexture& texture, const std::vector<double>& lambdasNm);

// The k values at uv, filtered bilinearly with repeat wrapping (texel centres at half-integers,
// v = 0 the top row: glTF's convention and GL_LINEAR's on the base level, as reference/surface_hit.h
// samples RGB textures). Filtering the values filters the reflectance: r is linear in them.
Eigen::VectorXd sampleTexels(const SpectralTexture& texture, const glm::vec2& uv);

// The reflectance of values c at one wavelength.
double reflectanceAt(const SpectralTexture& texture, const Eigen::VectorXd& c, double lambdaNm);

// What a texture must be, PRISM_CHECKed: sizes that agree, n ≥ 1, wavelengths strictly increasing
// and finite, the identity basis when `sampled`. The file reader checks each with a message first.
void checkSpectralTexture(const SpectralTexture& texture);

}  // namespace prism
