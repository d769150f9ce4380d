// cielab.glsl on the GPU vs the same file compiled as C++ (STYLE.md §4).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <iterator>
#include <limits>
#include <string>
#include <vector>

#include "gpu/gpu_test_support.h"
#include "shared_cpp.h"
#include "core/csv.h"
#include "core/data_files.h"

namespace prism::shared {
#include "cielab.glsl"
}

namespace prism::gpu {
namespace {

using glm::vec4;
using testing::GpuTest;
using testing::kUlp;
using testing::ParityReport;
using testing::Tolerance;

std::string describe(const vec4& a, const vec4& b) {
  char text[160];
  std::snprintf(text, sizeof text, "(%.9g, %.9g, %.9g) (%.9g, %.9g, %.9g)", a.x, a.y, a.z, b.x, b.y,
                b.z);
  return text;
}

// f(t) = labF(xyz / white) of one channel and the error both sides together may make in it:
// t carries a division (GLSL 2.5 ULP, C++ 0.5); the cube root is GLSL's pow (bound above) or
// C++'s powf (< 1 ULP); the linear segment is ×, + and ÷ (GLSL 3.5 ULP, C++ 1.5).
struct Channel {
  double f, error;
};

Channel labF(float xyz, float white) {
  const double epsilon = 216.0 / 24389.0, kappa = 24389.0 / 27.0;
  double t = static_cast<double>(xyz) / white;
  double tError = 3.0 * kUlp;
  if (t > epsilon) {
    double f = std::cbrt(t);
    return {f, f * (testing::glslPowRelativeError(t, 1.0f / 3.0f) + kUlp + tError / 3.0)};
  }
  double f = (kappa * t + 16.0) / 116.0;
  return {f, f * (5.0 * kUlp + tError)};
}

TEST_F(GpuTest, XyzToLabMatchesCpu) {
  const vec4 whites[] = {{0.95047f, 1.0f, 1.08883f, 0},
                         {0.96422f, 1.0f, 0.82521f, 0},
                         {1.09850f, 1.0f, 0.35585f, 0},
                         {95.047f, 100.0f, 108.883f, 0},
                         {1.0f, 1.0f, 1.0f, 0},
                         {0.73f, 0.27f, 0.0f, 0}};  // a 700 nm line: no Z, floored by labWhite
  const float epsilon = 216.0f / 24389.0f;
  testing::InputGenerator gen(0x1ab00001u);
  std::vector<vec4> xyz, white;
  auto add = [&](vec4 x, vec4 w) { xyz.push_back(x), white.push_back(w); };
  for (const vec4& w : whites) {
    add(w, w);            // white itself: (100, 0, 0)
    add(vec4(0.0f), w);   // black
    add(w * epsilon, w);  // on the branch point of f, and either side of it
    add(w * std::nextafter(epsilon, 1.0f), w);
    add(w * std::nextafter(epsilon, 0.0f), w);
    add(w * 1e-7f, w);  // near zero
    add(w * 1.5f, w);   // brighter than white (a specular highlight)
  }
  while (xyz.size() < 4096) {
    const vec4& w = whites[gen.bits() % std::size(whites)];
    float scale = gen.unit() < 0.2f ? 0.02f : 1.2f;  // a fifth near the linear segment
    add(vec4(gen.unit(), gen.unit(), gen.unit(), 0.0f) * scale * w, w);
  }
  Program kernel = testing::parityKernel("xyz_to_lab.comp");
  std::vector<vec4> gpu = testing::runParityKernel<vec4>(kernel, std::span<const vec4>(xyz),
                                                         std::span<const vec4>(white));
  // Tolerance: per value, the GLSL 4.50 §4.7.1 bound of f = pow(t, 1/3) (via exp2/log2) or of
  // the linear segment, scaled by 116, 500 or 200, plus each side's roundings. Reason: L*, a*,
  // b* are scaled differences of f, so their error is that of f times the scale.
  ParityReport l("xyzToLab.L", {}), a("xyzToLab.a", {}), b("xyzToLab.b", {});
  for (std::size_t i = 0; i < xyz.size(); ++i) {
    glm::vec3 cpu = shared::xyzToLab(glm::vec3(xyz[i]), glm::vec3(white[i]));
    std::string input = "xyzToLab" + describe(xyz[i], white[i]);
    const glm::vec3 w = shared::labWhite(glm::vec3(white[i]));
    Channel x = labF(xyz[i].x, w.x), y = labF(xyz[i].y, w.y), z = labF(xyz[i].z, w.z);
    double rounding = 4.0 * kUlp;  // k·f − c: ≤ 2 roundings per side
    l.compare(gpu[i].x, cpu.x, input, 116.0 * (y.error + rounding * y.f));
    a.compare(gpu[i].y, cpu.y, input, 500.0 * (x.error + y.error + rounding * std::max(x.f, y.f)));
    b.compare(gpu[i].z, cpu.z, input, 200.0 * (y.error + z.error + rounding * std::max(y.f, z.f)));
  }
  l.finish();
  a.finish();
  b.finish();
}

// Pairs of CIELAB colours: the 34 pairs of Sharma, Wu & Dalal 2005 (both orders), then
// neutral colours (hue undefined), identical pairs, small differences, random colours of
// ordinary and very large chroma.
void labPairs(std::vector<vec4>& lab1, std::vector<vec4>& lab2) {
  CsvTable sharma = CsvTable::read(dataFile("ciede2000_sharma.csv"));
  for (const CsvRow& row : sharma.rows()) {
    auto at = [&](int c) { return static_cast<float>(sharma.number(row, c)); };
    vec4 p(at(1), at(2), at(3), 0.0f), q(at(4), at(5), at(6), 0.0f);
    lab1.push_back(p), lab2.push_back(q);
    lab1.push_back(q), lab2.push_back(p);
  }
  testing::InputGenerator gen(0xde2000u);
  auto randomLab = [&](float chroma) {
    return vec4(100.0f * gen.unit(), gen.uniform(-chroma, chroma), gen.uniform(-chroma, chroma),
                0.0f);
  };
  for (int i = 0; i < 64; ++i) {
    vec4 neutral(100.0f * gen.unit(), 0.0f, 0.0f, 0.0f);
    vec4 tiny(100.0f * gen.unit(), gen.uniform(-1e-3f, 1e-3f), gen.uniform(-1e-3f, 1e-3f), 0.0f);
    vec4 colour = randomLab(100.0f);
    lab1.push_back(neutral), lab2.push_back(colour);  // one hue undefined
    lab1.push_back(colour), lab2.push_back(neutral);
    lab1.push_back(neutral), lab2.push_back(vec4(100.0f * gen.unit(), 0.0f, 0.0f, 0.0f));  // both
    lab1.push_back(tiny), lab2.push_back(neutral);
    lab1.push_back(colour), lab2.push_back(colour);  // identical: 0
    // On the a* axis (b* = 0, hue 0 or 180°), the wrap-around of hue angles.
    lab1.push_back(vec4(50.0f, gen.uniform(1.0f, 80.0f), 0.0f, 0.0f));
    lab2.push_back(vec4(50.0f, gen.uniform(1.0f, 80.0f), gen.uniform(-2.0f, 2.0f), 0.0f));
  }
  while (lab1.size() < 4096) {
    float chroma = gen.unit() < 0.25f ? 200.0f : 100.0f;  // a quarter of very large chroma
    vec4 p = randomLab(chroma);
    vec4 q = gen.unit() < 0.3f
                 ? p + vec4(gen.uniform(-1, 1), gen.uniform(-1, 1), gen.uniform(-1, 1), 0) * 0.5f
                 : randomLab(chroma);
    lab1.push_back(p), lab2.push_back(q);
  }
}

void checkDeltaE(const std::string& name, float (*cpu)(const glm::vec3&, const glm::vec3&),
                 Tolerance tolerance) {
  std::vector<vec4> lab1, lab2;
  labPairs(lab1, lab2);
  Program kernel = testing::parityKernel("delta_e.comp", {{"DELTA_E", name}});
  std::vector<float> gpu = testing::runParityKernel<float>(kernel, std::span<const vec4>(lab1),
                                                           std::span<const vec4>(lab2));
  ParityReport report(name, tolerance);
  for (std::size_t i = 0; i < lab1.size(); ++i)
    report.compare(gpu[i], cpu(glm::vec3(lab1[i]), glm::vec3(lab2[i])),
                   name + describe(lab1[i], lab2[i]));
  report.finish();
}

// Tolerance: 8 ULP. Reason: the differences round identically on both sides; dot() is ≤ 2
// roundings (fused or not), √ is 1/inversesqrt in GLSL (2 + 2.5 ULP), C++ adds 0.5 ULP.
TEST_F(GpuTest, DeltaE76MatchesCpu) { checkDeltaE("deltaE76", shared::deltaE76, {0.0, 0.0, 8}); }

// Tolerance: 2e-4 absolute (≈ 6 ULP of the largest chroma, 283, whose ULP is 3.05e-5).
// Reason: ΔC = C1 − C2 cancels, so the error is that of the chromas (each a √, GLSL 4.5 ULP),
// not a multiple of ΔE; the divisions by S_C, S_H add 2.5 ULP of terms ≤ ΔE.
TEST_F(GpuTest, DeltaE94MatchesCpu) { checkDeltaE("deltaE94", shared::deltaE94, {2e-4, 0.0, 0}); }

// Tolerance: 1e-3 absolute (a thousandth of a just-noticeable difference). Reason: GLSL leaves
// atan, sin and cos without a precision; llvmpipe's atan(y, x) is within 3.5e-6 rad of the
// exact value (glibc's atan2f 2.5e-7), and two hue angles off by that move
// ΔH' = 2·√(C1·C2)·sin(Δh/2) by ≤ 7e-6·C ≈ 2e-3 at C = 283, divided by S_H ≥ 2.2 there.
TEST_F(GpuTest, DeltaE2000MatchesCpu) {
  checkDeltaE("deltaE2000", shared::deltaE2000, {1e-3, 0.0, 0});
}

}  // namespace
}  // namespace prism::gpu
