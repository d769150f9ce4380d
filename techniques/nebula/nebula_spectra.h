// The spectral inputs of the nebula model (Barrès 2023, §3): stars' spectra, emission lines,
// passbands and their polynomial fits. Wavelengths are in µm throughout (the model's C_T and its
// exponent e^(−g/λ) are in µm); the files give nm.
#pragma once

#include <array>
#include <filesystem>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace prism::nebula {

// The attenuation's wavelength scale: τ(λ) = τ·C_T/λ (Barrès 2023, Eq. 2; valid above 0.25 µm).
inline constexpr double kCtUm = 0.56;
// Cardelli, Clayton & Mathis (1989, ApJ 345, 245), Eq. 1–3b: the interstellar extinction A(λ)/A(V)
// measured along many sightlines, for 0.3 ≤ 1/λ ≤ 3.3 µm⁻¹ (infrared and optical), as a function
// of R_V = A(V)/E(B − V) (3.1: the diffuse interstellar medium). The reference curve the model's
// C_T/λ attenuation is held to (`prism nebula extinction`). Error outside its range.
double ccmExtinction(double lambdaUm, double rv = 3.1);
// The model's attenuation relative to V (0.55 µm): τ(λ)/τ(V) = (C_T/λ)/(C_T/0.55) = 0.55/λ.
inline double modelExtinction(double lambdaUm) { return 0.55 / lambdaUm; }

// The band a render integrates over (the visible; the filters and CIE curves live inside it).
inline constexpr double kBandLoUm = 0.38;
inline constexpr double kBandHiUm = 0.78;
// The highest polynomial degree the shared integrals take (nebula_integrals.glsl: 8 coefficients).
inline constexpr int kMaxDegree = 7;

// A polynomial Σ cₙλⁿ (λ in µm) on [lambda0Um, lambda1Um], zero outside.
struct PolynomialPiece {
  double lambda0Um = 0.0;
  double lambda1Um = 0.0;
  std::array<double, kMaxDegree + 1> coeffs{};
  double at(double lambdaUm) const;
};

// Pieces on adjacent intervals; zero outside them.
struct PiecewisePolynomial {
  std::vector<PolynomialPiece> pieces;
  double at(double lambdaUm) const;
  double lambdaMinUm() const { return pieces.front().lambda0Um; }
  double lambdaMaxUm() const { return pieces.back().lambda1Um; }
};

// Least-squares fit of samples (λ in µm, value) over [loUm, hiUm] by `pieceCount` equal pieces of
// degree `degree`, each solved in the piece's own variable s ∈ [−1, 1] (well conditioned) and
// expanded to powers of λ in double. `relative`: each sample weighted by 1/|value| (the relative
// error's least squares).
PiecewisePolynomial fitPiecewisePolynomial(std::span<const double> lambdaUm, std::span<const double> values,
                                           double loUm, double hiUm, int pieceCount, int degree, bool relative = false);

// The product of two polynomials (degrees adding up to ≤ kMaxDegree), on a's interval; and of two
// piecewise ones, on the intersections of their pieces.
PolynomialPiece multiply(const PolynomialPiece& a, const PolynomialPiece& b);
PiecewisePolynomial multiply(const PiecewisePolynomial& a, const PiecewisePolynomial& b);

// A passband fitted by a piecewise polynomial P_S, and the fit's worst error (fraction of peak).
struct Passband {
  std::string name;
  PiecewisePolynomial response;
  double fitMaxErrorOfPeak = 0.0;
};

// Three passbands that make a pixel's three channels.
struct FilterSet {
  std::string name;  // "hubble" or "cie1931"
  std::array<Passband, 3> channels;
};

// The Hubble palette from data/hst_wfc3_uvis_filters.csv: [S II] → R (FQ672N: F673N is not in
// the data), Hα → G (F656N), [O III] → B (F502N); each fitted by quadratic pieces over its band (12, or one per 4 samples if fewer).
FilterSet hubblePalette(const std::filesystem::path& hstCsv);
// CIE 1931 x̄ ȳ z̄ (prism::cie1931Observer) over the band, each by 16 quadratic pieces.
FilterSet cieFilterSet();
// By name ("hubble", "cie1931"); Error naming it when unknown.
FilterSet filterSet(std::string_view name);

// A passband moved and resized, as the viewer's filter controls edit it: its response stretched
// `widthScale` times about the centre of its support (the same peak, a wider or narrower band),
// then moved `shiftNm` along: P'(λ) = P(c + (λ − c − shift)/scale). Each fitted piece stays a
// polynomial of its degree, so every method integrates the edited band as it did the fitted one.
struct PassbandEdit {
  double shiftNm = 0.0;     // in [−kMaxPassbandShiftNm, kMaxPassbandShiftNm]
  double widthScale = 1.0;  // in [kMinPassbandWidthScale, kMaxPassbandWidthScale]
  bool operator==(const PassbandEdit&) const = default;
};
inline constexpr double kMaxPassbandShiftNm = 200.0;
inline constexpr double kMinPassbandWidthScale = 0.25;
inline constexpr double kMaxPassbandWidthScale = 4.0;
// Pieces are clipped to the band [kBandLoUm, kBandHiUm]; Error naming the passband when none of it
// is left there, or when the edit is out of range.
Passband editedPassband(const Passband& band, const PassbandEdit& edit);
// Each channel by its edit; the set's name is kept.
FilterSet editedFilterSet(FilterSet set, const std::array<PassbandEdit, 3>& edits);

// Spectral radiance shapes of a star of temperature T (K) at λ (µm), up to a constant:
// Planck's B(λ,T) ∝ λ⁻⁵/(e^(hc/λkT) − 1), and Wien's approximation A/λ⁵·e^(−B/λ), B = hc/kT.
double planck(double lambdaUm, double temperatureK);
double wien(double lambdaUm, double temperatureK);

// Wien's B = hc/kT (µm): its shape is λ⁻⁵·e^(−B/λ), whose exponential joins the attenuation's.
double wienExponentUm(double temperatureK);

enum class StarModel { Planck, Wien };

// The dust's scattering over wavelength, σ(t, λ) = σ₁(t)·P_σ(λ) (Barrès 2023, §3): a polynomial
// of degree ≤ 3 on the band, ≥ 0 there. 1: grey dust.
PolynomialPiece greyScattering();
// Scattering in proportion to the measured extinction (dust of constant albedo): CCM's A(λ)/A(V),
// R_V = 3.1, fitted by a cubic over the band (within 2.0 % of it; nebula_test).
PolynomialPiece ccmScattering();
// The polynomial's degree (the highest non-zero coefficient's power).
int degree(const PolynomialPiece& p);

// A star's spectrum over the band, normalised to ∫ S dλ = 1 over [kBandLoUm, kBandHiUm] (µm⁻¹),
// times the dust's P_σ (what a star's scattered light carries: `at`), and the fit P_L of that
// product: two quintic pieces (a quadratic filter piece times one stays within the shared
// integrals' degree 7), which the analytic method integrates for a Planck star (a Wien star it
// integrates exactly, through negative powers of λ, while P_S·P_σ stays cubic).
struct StarSpectrum {
  double temperatureK = 5800.0;
  StarModel model = StarModel::Planck;
  double normalisation = 1.0;  // 1 / ∫ shape dλ (P_σ left out: it is the dust's, not the star's)
  PolynomialPiece scattering = greyScattering();  // P_σ
  PiecewisePolynomial fit;
  double fitMaxRelativeError = 0.0;
  double at(double lambdaUm) const;
  // The star's own light, normalised but without P_σ, at any λ (not only the band's).
  double shape(double lambdaUm) const;
};
// The star's normalisation alone (no P_σ, no fit): what shape() needs, for the light it sheds.
StarSpectrum starShape(double temperatureK, StarModel model);
// Its fit P_L: quintic pieces, as many as hold the spectrum (times P_σ) within 1e-4 relative, up
// to kMaxStarFitPieces.
inline constexpr int kMaxStarFitPieces = 16;
StarSpectrum makeStarSpectrum(double temperatureK, StarModel model, const PolynomialPiece& scattering = greyScattering());

// An emission line of ionised gas: a Dirac at λ (vacuum, µm) with a weight.
struct EmissionLine {
  std::string name;
  std::string group;
  double lambdaUm = 0.0;
  double ratio = 1.0;  // within its group, from the data
};
// data/nebula_lines.csv.
std::vector<EmissionLine> readEmissionLines(const std::filesystem::path& csv);


}  // namespace prism::nebula
