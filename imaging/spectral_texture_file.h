// Prism's spectral texture files (docs/spectral-texture.md): OpenEXR images whose channels are
// reflectance spectra, in one of two forms.
//   samples       one channel per wavelength, named as the spectral OpenEXR layout of Fichet,
//                 Pacanowski & Wilkie (JCGT 10(3), 2021) names reflective channels: "T.<λ>nm",
//                 the decimal separator a comma ("T.552,5nm"); any spectral EXR viewer opens them;
//   coefficients  channels "coefficient.0" … "coefficient.<k−1>" over k functions of the file's own,
//                 tabulated in string attributes: "prism:basisWavelengthsNm" (n numbers) and
//                 "prism:basis.<j>" (n numbers each).
// Row 0 is the image's top row (EXR's y runs down), which uv's v = 0 samples (glTF's convention).
#pragma once

#include <filesystem>

#include "spectral/spectral_texture.h"

namespace prism::imaging {

// Error "FILE: …" on one line when the file is not an EXR or is damaged, holds no spectral
// channels or both forms, names a channel it cannot read, repeats a wavelength, lacks or garbles
// a basis attribute, holds only some rows of an image, holds more than 2²⁸ values, or has a texel
// whose value is not finite or whose reflectance lies outside [0, 1] (by more than 0.01 for the
// coefficients form, whose basis may undershoot).
SpectralTexture readSpectralTexture(const std::filesystem::path& path);

// Float channels, ZIP-compressed, written atomically (core/atomic_file.h); the form is the
// texture's (`sampled`). PRISM_CHECKs the texture (checkSpectralTexture).
void writeSpectralTexture(const std::filesystem::path& path, const SpectralTexture& texture);

}  // namespace prism::imaging
