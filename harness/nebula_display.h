// A nebula's image for a screen (`prism nebula render -o X.png`, the gallery, `prism validate`):
// the Hubble palette stretched per channel to its own white level, as Hubble's images are made;
// natural colour (CIE 1931 XYZ) to sRGB, exposed by Y's white level. A white level is the
// channel's 99.5th percentile: the brightest 0.5 % clip.
#pragma once

#include <array>

#include "imaging/float_image.h"
#include "imaging/png_file.h"
#include "techniques/nebula/nebula_render.h"

namespace prism::harness {

// The white levels of R, G, B (`hubble`: the image holds the Hubble palette's R, G, B), or Y's
// three times (CIE 1931 X, Y, Z).
using NebulaWhite = std::array<double, 3>;
NebulaWhite nebulaWhiteLevels(const nebula::NebulaImage& image, bool hubble);

// What the screen shows before its clip and encoding, relative to `white`: each channel divided by
// its level — the palette's R, G, B (ColourMeaning::LinearSrgb, white 1), or X, Y, Z by Y's
// (ColourMeaning::Xyz, white 1).
imaging::FloatImage nebulaDisplayLinear(const nebula::NebulaImage& image, const NebulaWhite& white);

// The image on the screen, stretched to its own white levels or to given ones (another image's,
// so that two renders of one nebula are shown alike).
imaging::PngImage nebulaDisplayPng(const nebula::NebulaImage& image, bool hubble);
imaging::PngImage nebulaDisplayPng(const nebula::NebulaImage& image, bool hubble, const NebulaWhite& white);

}  // namespace prism::harness
