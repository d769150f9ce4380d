// spherical_harmonics.glsl and prt.glsl on the GPU vs the same files compiled as C++ (STYLE.md §4).
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "gpu/gpu_test_support.h"
#include "shared_cpp.h"

namespace prism::shared {
#include "spherical_harmonics.glsl"
#include "prt.glsl"
}

namespace prism::gpu {
namespace {

using testing::GpuTest;
using testing::ParityReport;

// One float rounding of a value of size s is at most s·2^-24; each bound below counts the
// roundings of a sum of products, as either side may fuse a multiply and add (GLSL §4.7.1
// allows it; the C++ build does not): per term 2 roundings of the term's size.
constexpr double kRounding = 0x1p-24;

TEST_F(GpuTest, SphericalHarmonicsAndPrtSumsMatchTheCpu) {
  testing::InputGenerator gen(0x5e1f0014u);
  std::vector<glm::vec4> dirs;
  // The poles and axes first (where terms vanish), then random unit directions.
  for (glm::vec3 d : {glm::vec3(0, 0, 1), glm::vec3(0, 0, -1), glm::vec3(1, 0, 0), glm::vec3(0, 1, 0),
                      glm::vec3(0, -1, 0), glm::vec3(-1, 0, 0)})
    dirs.emplace_back(d, 0.0f);
  while (dirs.size() < 4096) {
    glm::vec3 d(gen.uniform(-1, 1), gen.uniform(-1, 1), gen.uniform(-1, 1));
    float l = glm::length(d);
    if (l > 0.1f && l <= 1.0f) dirs.emplace_back(d / l, 0.0f);
  }
  std::vector<float> scene(400 + 64, 0.0f);
  shared::PrtEnvironment environment;
  shared::PrtReflectance reflectance;
  for (int j = 0; j < 16; ++j) {
    for (int k = 0; k < 25; ++k) scene[25 * j + k] = environment.basis[j].c[k] = gen.uniform(-1.0f, 1.0f);
    for (int c = 0; c < 3; ++c) scene[400 + 4 * j + c] = reflectance.r[j][c] = gen.uniform(0.0f, 1.0f);
  }

  Program kernel = testing::parityKernel("prt.comp");
  Buffer inA = Buffer::fromSpan(std::span<const glm::vec4>(dirs), "directions");
  inA.bindBase(GL_SHADER_STORAGE_BUFFER, 0);
  Buffer inB = Buffer::fromSpan(std::span<const float>(scene), "environment and reflectance");
  inB.bindBase(GL_SHADER_STORAGE_BUFFER, 1);
  Buffer out({dirs.size() * 29 * sizeof(float), nullptr, GL_DYNAMIC_STORAGE_BIT, "results"});
  out.bindBase(GL_SHADER_STORAGE_BUFFER, 2);
  kernel.setUniform("uCount", static_cast<GLuint>(dirs.size()));
  runCompute1D(kernel, dirs.size());
  std::vector<float> gpu = out.read<float>();
  ASSERT_EQ(gpu.size(), dirs.size() * 29);

  // Basis: a constant × a polynomial of degree ≤ 4 in x, y, z (|x|,|y|,|z| ≤ 1): at most 8
  // roundings of values ≤ 3 (the largest constant × 1) — 8 · 3 · 2^-24 absolute.
  ParityReport basis("shEvaluate", {8.0 * 3.0 * kRounding, 0.0, 0});
  // Sums: Ê_j = 25 products; XYZ = m products of Ê_j ≤ ~6 and R̂ ≤ 1, after the Ê's own error:
  // bounds scaled by the sums of absolute terms, computed per value below.
  ParityReport irradiance("prtVertexIrradiance", {0.0, 0.0, 0});
  ParityReport xyz("prtXyz", {0.0, 0.0, 0});
  for (std::size_t i = 0; i < dirs.size(); ++i) {
    glm::vec3 dir(dirs[i]);
    std::string input = "dir (" + std::to_string(dir.x) + ", " + std::to_string(dir.y) + ", " + std::to_string(dir.z) + ")";
    shared::Sh25 y = shared::shEvaluate(dir);
    for (int k = 0; k < 25; ++k) basis.compare(gpu[29 * i + k], y.c[k], input + " k=" + std::to_string(k));

    int m = 1 + static_cast<int>(i % 16);
    shared::Sh25 t = shared::shClampedCosine(dir);
    shared::PrtBasisIrradiance e = shared::prtVertexIrradiance(environment, t, m);
    glm::vec3 c = shared::prtXyz(e, reflectance, m);
    // |T̃_k| ≤ π·3 and its own error (a basis value's × Â_l): fold into the term sizes.
    double eBound = 0.0, xyzBound[3] = {0.0, 0.0, 0.0};
    for (int j = 0; j < m; ++j) {
      double terms = 0.0;
      for (int k = 0; k < 25; ++k) terms += std::abs(environment.basis[j].c[k] * t.c[k]);
      double bound = (2.0 * 25.0 + 8.0 * 3.0) * kRounding * terms + 1e-7;
      if (j == m - 1) eBound = bound;
      for (int ch = 0; ch < 3; ++ch)
        xyzBound[ch] += reflectance.r[j][ch] * (bound + 2.0 * m * kRounding * std::abs(e.e[j]));
    }
    irradiance.compare(gpu[29 * i + 28], e.e[m - 1], input + " m=" + std::to_string(m), eBound);
    for (int ch = 0; ch < 3; ++ch) xyz.compare(gpu[29 * i + 25 + ch], c[ch], input + " m=" + std::to_string(m), xyzBound[ch]);
  }
  basis.finish();
  irradiance.finish();
  xyz.finish();
}

}  // namespace
}  // namespace prism::gpu
