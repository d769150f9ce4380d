// Prints the chromaticity of D65 through an installed prism::spectral.
#include <cstdio>

#include "spectral/colour_space.h"
#include "spectral/illuminant.h"
#include "spectral/observer.h"

int main() {
  prism::Chromaticity xy =
      prism::xyzToXy(prism::observer("cie1931").integrate(prism::illuminant("D65")));
  std::printf("D65 xy %.4f %.4f\n", xy.x, xy.y);
  return 0;
}
