// Prints the chromaticity of D65, computed by the consumer's own library over prism::spectral.
#include <cstdio>
#include <string>

std::string d65Chromaticity();

int main() {
  std::printf("%s\n", d65Chromaticity().c_str());
  return 0;
}
