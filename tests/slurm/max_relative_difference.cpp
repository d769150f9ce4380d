// For the Slurm test (slurm_cluster_test.sh): the largest relative difference between two EXR
// images of one size, |a − b| / max(|a|, |b|) over every pixel's channels (0 where both are 0),
// printed as a number. Exit 1 with a line on stderr when they cannot be compared.
#include <cmath>
#include <cstdio>
#include <exception>

#include "core/worst_of.h"
#include "imaging/exr_file.h"

int main(int argc, char** argv) {
  if (argc != 3) {
    std::fprintf(stderr, "usage: %s A.exr B.exr\n", argv[0]);
    return 2;
  }
  try {
    const prism::imaging::FloatImage a = prism::imaging::readExr(argv[1]).image;
    const prism::imaging::FloatImage b = prism::imaging::readExr(argv[2]).image;
    if (a.width != b.width || a.height != b.height || a.channels != b.channels) {
      std::fprintf(stderr, "%s and %s differ in size\n", argv[1], argv[2]);
      return 1;
    }
    double worst = 0.0;
    for (std::size_t i = 0; i < a.pixels.size(); ++i) {
      const double x = a.pixels[i], y = b.pixels[i];
      if (x != y) worst = prism::worstOf(worst, std::abs(x - y) / std::max(std::abs(x), std::abs(y)));
    }
    std::printf("%.3g\n", worst);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "%s\n", e.what());
    return 1;
  }
  return 0;
}
