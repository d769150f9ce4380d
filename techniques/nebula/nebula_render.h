// A CPU ray marcher of a nebula (Barrès 2023) with the paper's four ways of integrating over
// wavelength, on the same ray samples so that only the spectral integration differs:
//   reference     Newton–Cotes over λ at every step (composite Simpson per filter piece, double)
//   analytic      the closed form per step: Σ over filter pieces × P_L of ∫ P(λ)e^(−g/λ) dλ
//                 (nebula_integrals.glsl, float), once per star
//   projection    e^(−g/λ) projected on the greedy exp(−a/λ) basis: the ray accumulates, per
//                 star, the coefficients on the orthonormalised basis (Σⱼ M(k,j)·∫ e^(−(g+aⱼ)/λ) dλ,
//                 float); card(B) filter integrals per star finish the pixel, so filters change
//                 without a new march
//   lightDensity  the 2D basis P_T(λ)e^(−a/λ): per voxel, the sum over stars of their light's
//                 projection (precomputed), so the march's cost does not depend on the star count
//   preIntegration the paper's rejected alternative: per star and channel, ∫ P_S S e^(−x/λ) dλ
//                 tabulated over x once (Catmull–Rom lookups); a filter change rebuilds the tables
// The model: density ρ on the unit cube; extinction τ = κ·∫ρ ds (τ(λ) = τ·C_T/λ, so the
// transmittance is e^(−g/λ) with g = τ·C_T in µm); scattering σ₁ρ·P_σ(λ) with an isotropic phase
// function (P_σ a polynomial, folded into each star's spectrum: StarSpectrum); stars as points of luminosity L and temperature T lighting each point
// through their own optical depth g_s (per voxel, precomputed); emission lines ε·ρ·Σ wₗ δ(λ−λₗ)
// (exact in every method), each group's ε·ρ times its ionisation zone when the model has zones
// (nebula_ionisation.h). A channel is ∫ P_S(λ)·L(λ) dλ through its fitted passband P_S.
#pragma once

#include <array>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "techniques/nebula/nebula_basis.h"
#include "techniques/nebula/nebula_density.h"
#include "techniques/nebula/nebula_ionisation.h"
#include "techniques/nebula/nebula_spectra.h"

namespace prism::nebula {

struct NebulaStar {
  glm::dvec3 position{0.5};    // in the unit cube's coordinates (may lie outside it)
  double temperatureK = 10000.0;
  double luminosity = 1.0;
};

// The largest side of a nebula's image, in pixels: a scene's camera, and every command's --size.
inline constexpr int kMaxImageSide = 8192;

struct NebulaCamera {
  glm::dvec3 position{0.5, 0.5, -1.0};
  glm::dvec3 target{0.5, 0.5, 0.5};
  double fovYDeg = 45.0;
  int width = 128;
  int height = 128;
};
// The camera's image scaled so that its longer side is `pixels` (≥ 1), the aspect kept.
void scaleImage(NebulaCamera& camera, int pixels);

// The camera's frame, which the CPU marcher and the GPU's view both build: forward towards the
// target, right and up square to it, up as near the world's +y as the view allows. A view along
// ±y, where +y gives no right, takes +z's side as up (the image turned, never a NaN ray).
struct NebulaViewFrame {
  glm::dvec3 forward, right, up;
};
NebulaViewFrame viewFrame(const NebulaCamera& camera);

// An emission-line group ("H I Balmer (case B)", "[O III] doublet", …, as in nebula_lines.csv)
// and the strength of its reference line (the one its ratios are relative to).
struct LineGroupStrength {
  std::string group;
  double strength = 0.0;
};

struct NebulaModel {
  DensityGrid density;
  double extinction = 4.0;   // κ: optical depth per unit length at ρ = 1
  double scattering = 1.0;   // σ₁: scattering per unit length at ρ = 1
  PolynomialPiece scatteringSpectrum = greyScattering();  // P_σ(λ), degree ≤ 3, ≥ 0 on the band
  double emission = 0.0;     // ε: emission per unit length at ρ = 1, times each group's strength
  std::vector<LineGroupStrength> lineGroups;
  // Where each group glows: everywhere the density is (none), or in its zone around the stars.
  std::optional<IonisationModel> ionisation;
  std::vector<NebulaStar> stars;
  StarModel starModel = StarModel::Planck;
  NebulaCamera camera;
  std::string filters = "hubble";  // "hubble" or "cie1931"
  std::array<PassbandEdit, 3> passbands{};  // each channel's passband moved and resized
};

enum class Method { Reference, Analytic, Projection, LightDensity, PreIntegration };
const char* methodName(Method m);
Method methodFromName(std::string_view name);  // Error naming it when unknown

// The settings' ranges (validate() below; a scene's keys, the command line and the viewer share them).
inline constexpr int kMaxSteps = 100000;
// The projection basis's elements: up to six orthonormalise in double (the Gram matrix's condition
// is 7e14 at six, 7e17 at seven, past double's 4.5e15); four is the most accurate (README: five and
// six amplify the moments' rounding more than they gain).
inline constexpr int kMaxBasisSize = 6;
inline constexpr int kMaxLightBasisSize = 16;
inline constexpr int kMaxReferenceIntervals = 1024;
inline constexpr int kMaxUniformSamples = 1000;
// The bases' family reaches no deeper than the coefficient table (kMomentTableMaxUm, 16 µm).
inline constexpr double kMaxBasisDepthUm = 16.0;

struct RenderSettings {
  Method method = Method::Reference;
  int steps = 100;               // ray samples between the cube's faces
  int referenceIntervals = 16;   // reference: Simpson intervals per filter piece (even)
  int uniformSamples = 0;        // reference: if > 0, that many λ per channel instead (trapezoid)
  int basisSize = 4;             // projection / lightDensity: card(B) of the 1D basis
  double basisSpacingUm = 0.2;   // its exponents' minimum spacing (nebula_basis.h; README)
  // Its family: attenuations g ∈ [0, this], its candidates' exponents a ∈ [0, max(2, this)]. Light
  // that reaches the camera through more dust (x = g + g_s beyond it) projects badly: the basis's
  // error there grows without bound (basisCoverage, nebula_basis_coverage.h, tells how much of a pixel's light does).
  double basisMaxDepthUm = 2.0;
  int lightBasisSize = 8;        // lightDensity: card of the 2D basis
  bool emissionLines = true;
  // The shared formulas in double (their f64 instantiation) instead of float, the GPU's
  // precision; the ray's accumulators are double either way.
  bool doublePrecision = false;
  // Projection and light–density: read the coefficients cₖ(x) = Σⱼ M(k,j)·mⱼ(x) of e^(−x/λ) on
  // the orthonormal basis (mⱼ(x) = ∫ e^(−(x+aⱼ)/λ) dλ) from a table over x (4096 entries on
  // [0, 16] µm, Catmull–Rom, float: what the GPU marcher reads too), built per frame from the
  // shared closed form in double, instead of evaluating the closed form (λ·E₂ at both bounds)
  // per sample; beyond the table, the closed form.
  bool momentTable = true;
  // Where each pixel's ray stops (a scene's surface in front of or inside the nebula), as a
  // distance from the camera in the cube's units, row 0 at the top; samples beyond it are left
  // out, the others keep their places. Empty: no ray stops (the GPU pass's twin, nebula_pass.h).
  std::vector<double> rayLimits;
  unsigned threads = 0;
};

// Error "nebula: steps 0 is not within 1..100000" (or the basis size, the light basis's, the
// reference's intervals or samples) unless every setting is within its range.
void validate(const RenderSettings& settings);

struct NebulaImage {
  int width = 0, height = 0;
  std::vector<glm::vec3> pixels;  // the filter set's three channels, row 0 at the top
};

// What a render precomputes from the model, independent of the method: filters, stars' spectra,
// per-star optical depth grids, the lines' responses. Built once, rendered with any method.
struct NebulaPrecomputed;
class NebulaRenderer {
 public:
  NebulaRenderer(NebulaModel model, const RenderSettings& basisSettings,
                 const std::function<void(std::size_t, std::size_t)>& progress = {});
  // The same volume through other filters or passbands: what the filters change is made again
  // (milliseconds), the stars' optical depths, the bases and the light–density coefficients are
  // copied. Renders as a renderer made from the edited model would, bit for bit.
  NebulaRenderer(const NebulaRenderer& volume, const std::string& filters, const std::array<PassbandEdit, 3>& passbands);
  ~NebulaRenderer();
  NebulaRenderer(const NebulaRenderer&) = delete;
  NebulaRenderer& operator=(const NebulaRenderer&) = delete;

  // progress, if set: rows done of the image's, serialised (core/parallel_for.h).
  NebulaImage render(const RenderSettings& settings,
                     const std::function<void(std::size_t done, std::size_t total)>& progress = {}) const;
  const ExpBasis& basis() const;
  const GreedyResult& lightBasis() const;
  const NebulaModel& model() const;

  // The reference method's wavelength nodes per channel and, per star, their weights P_S(λ)·w·S(λ):
  // composite Simpson over each passband piece (settings.referenceIntervals), or
  // settings.uniformSamples per channel by the trapezoid rule. The CPU and GPU marchers' one source.
  struct ReferenceNodes {
    std::array<std::vector<double>, 3> lambdaUm;
    std::vector<std::array<std::vector<double>, 3>> weights;  // [star][channel][node]
  };
  ReferenceNodes referenceNodes(const RenderSettings& settings) const;
  // What it precomputed (nebula_precomputed.h): the GPU marcher uploads these arrays.
  const NebulaPrecomputed& precomputed() const;
  // Builds pre-integration's tables if not yet (its first render does; the GPU marcher uploads them).
  void preparePreIntegration() const;

 private:
  std::unique_ptr<NebulaPrecomputed> mPre;
};

// Per channel, over pixels whose reference value is at least `floorOfMax` × that channel's
// maximum: the largest |image − reference| / reference; infinite where either image has a pixel
// that is not finite (anywhere, not only over the floor); NaN where no pixel is compared, the
// reference being black (0 read as a perfect match: a camera looking away, a nebula without light).
double maxRelativeError(const NebulaImage& image, const NebulaImage& reference, double floorOfMax = 0.01);

}  // namespace prism::nebula
