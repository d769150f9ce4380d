// D65's chromaticity through an installed prism::spectral, in a static library of the consumer's.
#include <cstdio>
#include <string>

#include "spectral/colour_space.h"
#include "spectral/illuminant.h"
#include "spectral/observer.h"

std::string d65Chromaticity() {
  prism::Chromaticity xy = prism::xyzToXy(prism::observer("cie1931").integrate(prism::illuminant("D65")));
  char text[64];
  std::snprintf(text, sizeof text, "D65 xy %.4f %.4f", xy.x, xy.y);
  return text;
}
