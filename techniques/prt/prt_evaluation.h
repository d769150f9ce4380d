// Spectral PRT evaluated on the CPU, per vertex, with its two baselines through the same transfer
// and the same run-time sums (shaders/shared/prt.glsl):
//   spectral  m SVD basis functions (Schwenk, Kuijper & Bockholt);
//   RGB-PRT   three channels: the environment's and the albedo's linear RGB in a colour space,
//             multiplied per channel (the common practice the paper improves on);
//   reference point sampling at 5 nm, 81 wavelengths over 380–780 nm (the paper's reference).
// Differences between spectral and reference are therefore purely spectral: the SH band limit and
// the visibility are the same in both.
//
// Environments are distant and spectral, L(ω, λ) = Σ_t S_t(λ) g_t(ω), each g_t projected on SH-5;
// the zenith is +z. Colours are XYZ on the scale of the integrals; CIELAB and ΔE are taken
// relative to the scene white, the reference's perfect white reflector facing the zenith
// unshadowed. For display, Bradford adaptation from that white to the display's.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include <Eigen/Core>
#include <glm/glm.hpp>

#include "spectral/colour_space.h"
#include "spectral/observer.h"
#include "spectral/spectrum.h"
#include "techniques/prt/prt_spectra.h"
#include "techniques/prt/sh_tools.h"
#include "techniques/prt/transfer_bake.h"

namespace prism::prt {

struct EnvironmentTerm {
  Spectrum spectrum;      // S_t(λ), radiance per unit of g
  ShVector directional;   // g_t(ω) on SH-5
};

struct SpectralEnvironment {
  std::string name;
  std::vector<EnvironmentTerm> terms;
};

// The same radiance from every direction.
SpectralEnvironment uniformEnvironment(std::string name, const Spectrum& spd);
// The CIE overcast sky's gradient (Moon & Spencer 1942; CIE S 011/E:2003, type 1: L(θ) = L_z·(1 +
// 2 cos θ)/3) above the horizon, with L_z = spd, and below it a grey ground of albedo
// `groundAlbedo` lit by that sky (radiance albedo·E_h/π, E_h = 7π/9·L_z).
inline constexpr double kSkyGroundAlbedo = 0.2;
// The gradient's relative radiance at a direction of zenith cosine z: (1 + 2z)/3 above the
// horizon, albedo·7/9 below (the ground lit by the sky above it).
inline double skyGradient(double z, double groundAlbedo = kSkyGroundAlbedo) {
  return z >= 0.0 ? (1.0 + 2.0 * z) / 3.0 : groundAlbedo * 7.0 / 9.0;  // albedo · (7π/9 · L_z) / π
}
SpectralEnvironment skyGradientEnvironment(std::string name, const Spectrum& spd, double groundAlbedo = kSkyGroundAlbedo);
// Texel (x, y) of a width × height equirectangular grid (row 0 at the zenith +z, u = φ/2π from +x
// towards +y): its centre's direction and its exact solid angle (2π/width)·(cos θ0 − cos θ1).
struct EquirectangularTexel {
  glm::dvec3 direction;
  double solidAngle = 0.0;
};
EquirectangularTexel equirectangularTexel(int x, int y, int width, int height);
// The 25 SH functions integrated over texel (x, y): the map as the piecewise-constant radiance the
// path tracer samples. The texel is split into s × s cells, s making the grid at least
// kTexelShCellsAcross cells wide, each cell its exact solid angle times the functions at its
// centre. A texel's centre alone missed the higher bands of small maps: a constant 1×1 map had
// bands 1–4 at 2.2× its band 0 (negative light on half the sphere), a 64×32 one at 3e-3.
inline constexpr int kTexelShCellsAcross = 512;
ShVector equirectangularTexelSh(int x, int y, int width, int height);
// The texel whose solid angle holds a direction (need not be unit).
glm::ivec2 equirectangularTexelOf(const glm::dvec3& direction, int width, int height);
// Its terms' spectra on the 5 nm grid, in order: one group of SpectralBasis.
std::vector<Eigen::VectorXd> termSpectra(const SpectralEnvironment& environment);
// An environment from its 25 SH coefficients' spectra on the 5 nm grid (81 × 25; linear between
// grid wavelengths).
SpectralEnvironment gridEnvironment(std::string name, const Eigen::MatrixXd& grid);
// An equirectangular map (row 0 at the zenith +z, u = φ/2π from +x towards +y), linear RGB per
// texel as `width × height` triples, each texel upsampled by `toSpectrum` (a texel is light, so
// Prism's illuminant RGB intent: RgbIlluminantSpectrum(table, space, rgb).toDense(), white the
// space's white) and projected by equirectangularTexelSh.
// Held as 25 terms, the spectrum of each SH coefficient on the 5 nm
// grid (linear between grid wavelengths), so rotation and the basis's columns work as for the
// analytic environments. Error "SOURCE: texel (x, y): …" for a negative or non-finite value.
SpectralEnvironment equirectangularEnvironment(std::string name, int width, int height,
                                               const std::vector<float>& linearRgb,
                                               const std::function<Spectrum(const glm::vec3& rgb)>& toSpectrum);
// Turned by R (orthonormal, det +1) through the SH rotation: no projection again.
SpectralEnvironment rotateEnvironment(const SpectralEnvironment& environment, const glm::dmat3& rotation);
// L_ik = Σ_t S_t(λ_i) g_tk on the 5 nm grid: 81 × 25.
Eigen::MatrixXd environmentOnGrid(const SpectralEnvironment& environment);

// A PRT object: a mesh, a material per vertex and the materials' reflectances.
struct PrtObject {
  PrtMesh mesh;
  std::vector<int> vertexMaterial;
  std::vector<Spectrum> reflectances;
  std::vector<std::string> materialNames;
};

// The ColorChecker's 24 patches on a self-shadowing height field in the x-y plane (z up): a
// 6 × 4 grid of unit cells, each a bump z = 0.6·sin²(πx)·sin²(πy) carrying one patch in chart
// order, so that each bump shades its neighbours' feet. verticesPerPatch along each side (≥ 2).
PrtObject makeColourCheckerObject(int verticesPerPatch = 16);

// What the run-time sums take, as the GPU takes it (shaders/shared/prt.glsl): the environment's
// rows L̃ (basisCount × 25) and, per reflectance, R̂ (3 × basisCount), basisCount ≤ 16. A mode is
// one or more of them, summed: spectral PRT and RGB-PRT one, the 5 nm reference six chunks of at
// most 16 deltas. The CPU shading below and the renderer's forward pass both draw from these.
struct PrtProjection {
  int basisCount = 0;
  shared::PrtEnvironment environment{};
  std::vector<shared::PrtReflectance> reflectances;
  // Where the basis functions are sampled in wavelength, for a medium's T(λ) (prt_medium.h):
  // node q at nodeWavelengthsNm[q] with a_qj = nodeBasis(q, j) (j < basisCount).
  std::vector<double> nodeWavelengthsNm;
  Eigen::MatrixXd nodeBasis;
  // Per reflectance, per node, its ρ_q: f_r(λ_q)·c̄(λ_q)·5 nm (RGB-PRT: R̂_q).
  std::vector<std::vector<glm::vec3>> nodeReflectances;
};
// Spectral PRT: L̃ = Φᵀ L, R̂_j = Σ_i φ_j(λ_i) f_r(λ_i) c̄(λ_i) · 5 nm; basis 81 × m, m ≤ 16.
PrtProjection projectSpectral(const std::vector<Spectrum>& reflectances, const Eigen::MatrixXd& environmentGrid,
                              const Observer& observer, const Eigen::MatrixXd& basis);
// Error under any observer but CIE 1931, on which RGB-PRT's colours are defined.
void requireRgbPrtObserver(const Observer& observer);
// RGB-PRT in `space`: L̃ the environment's linear RGB per SH coefficient, R̂_c = albedo_c · primary
// c's XYZ, albedos the reflectances' colours under CIE D65. requireRgbPrtObserver first.
PrtProjection projectRgb(const std::vector<Spectrum>& reflectances, const Eigen::MatrixXd& environmentGrid,
                         const Observer& observer, const RgbColourSpace& space);
// The 5 nm reference: 81 deltas, R̂_i = f_r(λ_i) c̄(λ_i) · 5 nm, in chunks of 16.
std::vector<PrtProjection> projectReference(const std::vector<Spectrum>& reflectances,
                                            const Eigen::MatrixXd& environmentGrid, const Observer& observer);

// Per-vertex XYZ, each through prtVertexIrradiance and prtXyz.
std::vector<Eigen::Vector3d> shadeReference(const PrtObject& object, const std::vector<shared::Sh25>& transfer,
                                            const Eigen::MatrixXd& environmentGrid, const Observer& observer);
// basis: 81 × m orthonormal columns, m ≤ 16.
std::vector<Eigen::Vector3d> shadeSpectral(const PrtObject& object, const std::vector<shared::Sh25>& transfer,
                                           const Eigen::MatrixXd& environmentGrid, const Observer& observer,
                                           const Eigen::MatrixXd& basis);
// Albedos are the reflectances' linear RGB under CIE D65 (the white of sRGB, P3, Rec.2020).
std::vector<Eigen::Vector3d> shadeRgb(const PrtObject& object, const std::vector<shared::Sh25>& transfer,
                                      const Eigen::MatrixXd& environmentGrid, const Observer& observer,
                                      const RgbColourSpace& space);

// The reference XYZ of a perfect white reflector facing +z, unshadowed.
Eigen::Vector3d sceneWhite(const Eigen::MatrixXd& environmentGrid, const Observer& observer);

struct DeltaEStatistics {
  double mean94 = 0.0, max94 = 0.0, mean2000 = 0.0, max2000 = 0.0;
};
DeltaEStatistics compareShading(const std::vector<Eigen::Vector3d>& test, const std::vector<Eigen::Vector3d>& reference,
                                const Eigen::Vector3d& whiteXyz);

// Display colours: Bradford from the scene white to the space's white, exposure so that the
// scene white has Y = 1, linear RGB clamped to [0, 1] and encoded.
std::vector<Eigen::Vector3d> displayColours(const std::vector<Eigen::Vector3d>& xyz, const Eigen::Vector3d& whiteXyz,
                                            const RgbColourSpace& space);

struct BasisSweepRow {
  int m = 0;
  double capturedEnergy = 0.0;
  DeltaEStatistics error;  // spectral PRT with m functions against the 5 nm reference
};
struct PrtReport {
  std::size_t vertices = 0;
  std::vector<BasisSweepRow> sweep;  // m = 1..16 (or as many as the spectra allow)
  DeltaEStatistics rgbError;         // RGB-PRT (sRGB) against the reference
};
// The basis is the SVD of every reflectance of the object and every spectrum of the environment.
PrtReport basisSweep(const PrtObject& object, const std::vector<shared::Sh25>& transfer,
                     const SpectralEnvironment& environment, const Observer& observer, int maxBasis = 16);

// The paper's metamer scene ("Metacow"): two reflectances (a patch and its metamer) on the same
// object, rendered by spectral PRT with the basis of both reflectances and every environment's
// spectra (m = min(maxBasis, that many)); per environment, ΔE between the two shadings at each
// vertex (the two halves of the object, compared where the light is the same).
std::vector<DeltaEStatistics> metamerHalves(const PrtObject& object, const std::vector<shared::Sh25>& transfer,
                                            const Spectrum& a, const Spectrum& b,
                                            const std::vector<SpectralEnvironment>& environments,
                                            const Observer& observer, int maxBasis = 8);

}  // namespace prism::prt
