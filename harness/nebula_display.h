// A nebula's image for a screen (`prism nebula render -o X.png`, the gallery): the Hubble palette
// stretched per channel to its own white level, as Hubble's images are made; natural colour (CIE
// 1931 XYZ) to sRGB, exposed by Y's white level. A white level is the channel's 99.5th
// percentile: the brightest 0.5 % clip.
#pragma once

#include "imaging/png_file.h"
#include "techniques/nebula/nebula_render.h"

namespace prism::harness {

// `hubble`: the image holds the Hubble palette's R, G, B; else CIE 1931 X, Y, Z.
imaging::PngImage nebulaDisplayPng(const nebula::NebulaImage& image, bool hubble);

}  // namespace prism::harness
