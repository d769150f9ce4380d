// What a nebula render precomputes from its model, independent of the method (NebulaRenderer
// builds it once): the filters and stars' spectra, each star's optical depth per voxel, the
// lines' responses, the bases and their finishing weights, the moment table. Its own header
// because two marchers read it: the CPU one (nebula_render.cpp) and the GPU one
// (gpu/nebula_gpu_marcher.cpp), which uploads these very arrays, so that both march the same data.
#pragma once

#include <array>
#include <functional>
#include <mutex>
#include <vector>

#include <Eigen/Core>
#include <glm/glm.hpp>

#include "techniques/nebula/nebula_analytic_pieces.h"
#include "techniques/nebula/nebula_basis.h"
#include "techniques/nebula/nebula_density.h"
#include "techniques/nebula/nebula_integrals.h"
#include "techniques/nebula/nebula_render.h"
#include "techniques/nebula/nebula_spectra.h"

namespace prism::nebula {

// A grid of per-voxel values at the density's resolution (voxel centres), `width` values each.
struct VoxelField {
  int nx = 0, ny = 0, nz = 0, width = 1;
  std::vector<float> values;
  // Trilinear between voxel centres, clamped at the faces, into out[0..width).
  void sample(const glm::dvec3& p, float* out) const {
    const TrilinearAxis ax = trilinearAxis(p.x, nx), ay = trilinearAxis(p.y, ny), az = trilinearAxis(p.z, nz);
    const int x0 = ax.i0, x1 = ax.i1, y0 = ay.i0, y1 = ay.i1, z0 = az.i0, z1 = az.i1;
    const double fx = ax.f, fy = ay.f, fz = az.f;
    for (int c = 0; c < width; ++c) out[c] = 0.0f;
    const int xs[2] = {x0, x1}, ys[2] = {y0, y1}, zs[2] = {z0, z1};
    const double wx[2] = {1 - fx, fx}, wy[2] = {1 - fy, fy}, wz[2] = {1 - fz, fz};
    for (int a = 0; a < 2; ++a)
      for (int b = 0; b < 2; ++b)
        for (int d = 0; d < 2; ++d) {
          auto w = static_cast<float>(wx[a] * wy[b] * wz[d]);
          std::size_t at = (static_cast<std::size_t>((zs[d] * ny + ys[b]) * nx + xs[a])) * static_cast<std::size_t>(width);
          for (int c = 0; c < width; ++c) out[c] += w * values[at + static_cast<std::size_t>(c)];
        }
  }
};

// The coefficients cₖ(x) = Σⱼ M(k,j)·mⱼ(x) of e^(−x/λ) on the orthonormal basis, tabulated over
// x ∈ [0, kMomentTableMaxUm] (from the raw moments mⱼ in double). The march accumulates these,
// not the raw moments: the raw moments of nearby exponentials are nearly parallel, and M's rows
// alternate in sign, so Σ W'ⱼ·mⱼ over accumulated raw moments cancels to ~1/6000 of its terms
// (measured on the twin test's nebula) and float's rounding of the sums would show at 1e-3.
constexpr int kMomentTableSize = 4096;
constexpr double kMomentTableMaxUm = 16.0;
struct MomentTable {
  std::vector<glm::vec4> lo, hi;  // size + 3 entries: one before 0, two after the end
  int size = kMomentTableSize;
  double step = kMomentTableMaxUm / (kMomentTableSize - 1);
  // Catmull–Rom between entries; false beyond the table.
  bool lookup(double x, glm::vec4& mLo, glm::vec4& mHi, bool withHi) const {
    double u = x / step;
    if (!(u < size - 1)) return false;
    int i = static_cast<int>(u);
    auto t = static_cast<float>(u - i);
    const glm::vec4 w = shared::nebulaCatmullRomWeights(t);
    const float w0 = w.x, w1 = w.y, w2 = w.z, w3 = w.w;
    auto at = static_cast<std::size_t>(i);  // entry i + 1 holds x = i·step
    mLo = w0 * lo[at] + w1 * lo[at + 1] + w2 * lo[at + 2] + w3 * lo[at + 3];
    if (withHi) mHi = w0 * hi[at] + w1 * hi[at + 1] + w2 * hi[at + 2] + w3 * hi[at + 3];
    return true;
  }
};

struct NebulaPrecomputed {
  NebulaModel model;
  FilterSet filters;
  std::vector<StarSpectrum> spectra;
  std::vector<VoxelField> starDepth;  // g_s per voxel (µm), one field per star
  // Emission lines: each line's λ, its weight (its group's strength × its ratio) and its
  // response per channel (P_S(λₗ)·weight).
  std::vector<double> lineLambdaUm;
  std::vector<double> lineWeight;
  std::vector<glm::dvec3> lineResponse;
  // Ionisation zones (the model's, when it has them): per voxel one value per zone, and per line
  // the zone it glows in (empty without zones: every line glows wherever the density is).
  VoxelField lineZones;
  std::vector<int> lineZone;
  // Analytic: per star and channel, its pieces (nebula_analytic_pieces.h).
  AnalyticPieces analytic;
  // Projection: the 1D basis and its table of coefficients.
  ExpBasis basis;
  glm::vec4 basisLo{0.0f}, basisHi{0.0f};  // exponents a₀…a₇ in float, as the GPU and the float path take them
  // The same exponents in double (a₀…a₃, or a₄…a₇ for `half` 1; 0 where unused), as toCoefficients'
  // orthonormalisation took them: raw moments in double must use these. With the float ones the
  // table of coefficients carried their rounding (6e-8) through the ill-conditioned fifth row:
  // the example's five-element projection was 0.74 % from the reference instead of 0.049 %.
  glm::dvec4 exponents(int half) const {
    glm::dvec4 a(0.0);
    for (int j = 0; j < 4; ++j)
      if (const auto k = static_cast<std::size_t>(4 * half + j); k < basis.a.size()) a[j] = basis.a[k];
    return a;
  }
  MomentTable moments;
  // Pre-integration: per star, the three channels' ∫ P_S S_s e^(−x/λ) dλ over x (in lo.xyz),
  // 4096 entries; built at its first render.
  std::once_flag preIntegratedOnce;
  std::vector<MomentTable> preIntegrated;
  // Projection: per star and channel, Wₖ = ∫ P_S S_s bₖ dλ on the orthonormal basis.
  std::vector<std::array<std::array<double, 8>, 3>> projectionWeights;
  // Raw moments → coefficients: c[k] = Σ_{j≤k} M(k,j)·raw[j].
  void toCoefficients(const std::array<double, 8>& raw, std::array<double, 8>& c) const {
    c.fill(0.0);
    for (Eigen::Index k = 0; k < basis.m.rows(); ++k)
      for (Eigen::Index j = 0; j <= k; ++j) c[static_cast<std::size_t>(k)] += basis.m(k, j) * raw[static_cast<std::size_t>(j)];
  }
  // Light–density: the 2D basis, its per-voxel coefficients, and the finish's weights U.
  GreedyResult lightGreedy;
  VoxelField lightCoefficients;
  std::vector<double> lightU;  // [c][k][m] = ∫ P_S,c fₖ bₘ dλ, k < lightCount, m < card(B)
  int lightCount = 0;
  std::function<double(int k, double lambdaUm)> lightFunction;  // fₖ(λ), the orthonormal 2D basis
  // What depends on the filters (NebulaRenderer's refiltering constructor makes these again and
  // copies the rest): filters, lineResponse, analytic,
  // projectionWeights, lightU, preIntegrated.
};

}  // namespace prism::nebula
