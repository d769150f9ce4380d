#include "techniques/nebula/nebula_spectra.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include <Eigen/Dense>
#include <fmt/format.h>

#include "core/csv.h"
#include "core/data_files.h"
#include "core/error.h"
#include "core/gauss_legendre.h"
#include "core/worst_of.h"
#include "spectral/observer.h"

namespace prism::nebula {

double PolynomialPiece::at(double lambdaUm) const {
  if (lambdaUm < lambda0Um || lambdaUm > lambda1Um) return 0.0;
  double v = 0.0;
  for (int n = kMaxDegree; n >= 0; --n) v = v * lambdaUm + coeffs[static_cast<std::size_t>(n)];
  return v;
}

double PiecewisePolynomial::at(double lambdaUm) const {
  for (const auto& p : pieces)
    if (lambdaUm >= p.lambda0Um && lambdaUm <= p.lambda1Um) return p.at(lambdaUm);
  return 0.0;
}

PiecewisePolynomial fitPiecewisePolynomial(std::span<const double> lambdaUm, std::span<const double> values,
                                           double loUm, double hiUm, int pieceCount, int degree, bool relative) {
  PRISM_CHECK(lambdaUm.size() == values.size() && pieceCount >= 1 && degree >= 0 && degree <= kMaxDegree);
  PiecewisePolynomial result;
  for (int p = 0; p < pieceCount; ++p) {
    double a = loUm + (hiUm - loUm) * p / pieceCount, b = loUm + (hiUm - loUm) * (p + 1) / pieceCount;
    double c = 0.5 * (a + b), h = 0.5 * (b - a);
    std::vector<std::pair<double, double>> rows;
    for (std::size_t i = 0; i < lambdaUm.size(); ++i)
      if (lambdaUm[i] >= a && lambdaUm[i] <= b) rows.emplace_back((lambdaUm[i] - c) / h, values[i]);
    PRISM_CHECK(static_cast<int>(rows.size()) > degree);
    Eigen::MatrixXd A(static_cast<Eigen::Index>(rows.size()), degree + 1);
    Eigen::VectorXd y(static_cast<Eigen::Index>(rows.size()));
    for (std::size_t r = 0; r < rows.size(); ++r) {
      const double weight = relative && rows[r].second != 0.0 ? 1.0 / std::abs(rows[r].second) : 1.0;
      double s = weight;
      for (int k = 0; k <= degree; ++k, s *= rows[r].first) A(static_cast<Eigen::Index>(r), k) = s;
      y(static_cast<Eigen::Index>(r)) = weight * rows[r].second;
    }
    Eigen::VectorXd q = A.colPivHouseholderQr().solve(y);
    // q in s = (λ − c)/h; expand Σ q_k (λ − c)^k / h^k into powers of λ.
    PolynomialPiece piece{a, b, {}};
    for (int k = 0; k <= degree; ++k) {
      double scale = q(k) / std::pow(h, k);
      double binom = 1.0;
      for (int j = 0; j <= k; ++j) {  // (λ − c)^k = Σ_j C(k,j) λ^j (−c)^(k−j)
        piece.coeffs[static_cast<std::size_t>(j)] += scale * binom * std::pow(-c, k - j);
        binom = binom * (k - j) / (j + 1);
      }
    }
    result.pieces.push_back(piece);
  }
  return result;
}

PolynomialPiece multiply(const PolynomialPiece& a, const PolynomialPiece& b) {
  PolynomialPiece r{a.lambda0Um, a.lambda1Um, {}};
  for (std::size_t i = 0; i <= kMaxDegree; ++i)
    for (std::size_t j = 0; j <= kMaxDegree; ++j) {
      if (a.coeffs[i] == 0.0 || b.coeffs[j] == 0.0) continue;
      PRISM_CHECK(i + j <= kMaxDegree);
      r.coeffs[i + j] += a.coeffs[i] * b.coeffs[j];
    }
  return r;
}

PiecewisePolynomial multiply(const PiecewisePolynomial& a, const PiecewisePolynomial& b) {
  PiecewisePolynomial r;
  for (const auto& pa : a.pieces)
    for (const auto& pb : b.pieces) {
      double lo = std::max(pa.lambda0Um, pb.lambda0Um), hi = std::min(pa.lambda1Um, pb.lambda1Um);
      if (hi <= lo) continue;
      PolynomialPiece piece = multiply(pa, pb);
      piece.lambda0Um = lo;
      piece.lambda1Um = hi;
      r.pieces.push_back(piece);
    }
  return r;
}

namespace {

Passband fitPassband(std::string name, const std::vector<double>& lambdaUm, const std::vector<double>& values,
                     double loUm, double hiUm, int pieces) {
  Passband band{std::move(name), fitPiecewisePolynomial(lambdaUm, values, loUm, hiUm, pieces, 2), 0.0};
  double peak = *std::max_element(values.begin(), values.end()), worst = 0.0;
  for (std::size_t i = 0; i < lambdaUm.size(); ++i)
    if (lambdaUm[i] >= loUm && lambdaUm[i] <= hiUm)
      worst = worstOf(worst, std::abs(band.response.at(lambdaUm[i]) - values[i]));
  band.fitMaxErrorOfPeak = worst / peak;
  return band;
}

}  // namespace

FilterSet hubblePalette(const std::filesystem::path& hstCsv) {
  CsvTable table = CsvTable::read(hstCsv);
  int lambdaCol = table.column("wavelength_nm"), filterCol = table.column("filter"),
      valueCol = table.column("throughput");
  FilterSet set{"hubble", {}};
  const char* names[3] = {"FQ672N", "F656N", "F502N"};
  for (std::size_t c = 0; c < 3; ++c) {
    std::vector<double> lambdaUm, values;
    for (const auto& row : table.rows()) {
      if (row.fields[static_cast<std::size_t>(filterCol)] != names[c]) continue;
      lambdaUm.push_back(table.number(row, lambdaCol) * 1e-3);
      values.push_back(table.number(row, valueCol));
    }
    if (lambdaUm.size() < 12)
      throw Error(FileLocation{table.path()}, fmt::format("filter {}: {} samples, need at least 12", names[c], lambdaUm.size()));
    set.channels[c] = fitPassband(names[c], lambdaUm, values, lambdaUm.front(), lambdaUm.back(),
                                  std::min(12, static_cast<int>(lambdaUm.size()) / 4));
  }
  return set;
}

FilterSet cieFilterSet() {
  const Observer& obs = cie1931Observer();
  FilterSet set{"cie1931", {}};
  const char* names[3] = {"x_bar", "y_bar", "z_bar"};
  std::vector<double> lambdaUm;
  for (int nm = 380; nm <= 780; ++nm) lambdaUm.push_back(nm * 1e-3);
  for (std::size_t c = 0; c < 3; ++c) {
    std::vector<double> values;
    for (double l : lambdaUm) values.push_back(obs.at(l * 1e3)[static_cast<Eigen::Index>(c)]);
    set.channels[c] = fitPassband(names[c], lambdaUm, values, kBandLoUm, kBandHiUm, 16);
  }
  return set;
}

FilterSet filterSet(std::string_view name) {
  if (name == "hubble") return hubblePalette(dataFile("hst_wfc3_uvis_filters.csv"));
  if (name == "cie1931") return cieFilterSet();
  throw Error(fmt::format("unknown filter set '{}' (hubble, cie1931)", excerpt(name)));
}

Passband editedPassband(const Passband& band, const PassbandEdit& edit) {
  if (!(std::abs(edit.shiftNm) <= kMaxPassbandShiftNm) ||
      !(edit.widthScale >= kMinPassbandWidthScale && edit.widthScale <= kMaxPassbandWidthScale))
    throw Error(fmt::format("passband {}: a shift of {} nm (at most ±{}) or a width × {} (within {}–{})", band.name,
                            edit.shiftNm, kMaxPassbandShiftNm, edit.widthScale, kMinPassbandWidthScale,
                            kMaxPassbandWidthScale));
  if (edit == PassbandEdit{}) return band;
  const double centre = 0.5 * (band.response.lambdaMinUm() + band.response.lambdaMaxUm());
  const double moved = centre + edit.shiftNm * 1e-3, scale = edit.widthScale;
  // P(αλ + β), α = 1/scale, β = centre − moved/scale: Σₙ aₙ(αλ + β)ⁿ expanded by the binomial theorem.
  const double alpha = 1.0 / scale, beta = centre - moved / scale;
  Passband out{band.name, {}, band.fitMaxErrorOfPeak};
  for (const PolynomialPiece& piece : band.response.pieces) {
    PolynomialPiece p;
    p.lambda0Um = std::max(kBandLoUm, moved + (piece.lambda0Um - centre) * scale);
    p.lambda1Um = std::min(kBandHiUm, moved + (piece.lambda1Um - centre) * scale);
    if (!(p.lambda1Um > p.lambda0Um)) continue;
    for (int n = 0; n <= kMaxDegree; ++n) {
      double binomial = 1.0;  // C(n, k)
      for (int k = 0; k <= n; ++k) {
        p.coeffs[static_cast<std::size_t>(k)] +=
            piece.coeffs[static_cast<std::size_t>(n)] * binomial * std::pow(alpha, k) * std::pow(beta, n - k);
        binomial = binomial * (n - k) / (k + 1);
      }
    }
    out.response.pieces.push_back(p);
  }
  if (out.response.pieces.empty())
    throw Error(fmt::format("passband {}: moved {} nm and × {} wide, nothing of it is left in {}–{} nm", band.name,
                            edit.shiftNm, edit.widthScale, kBandLoUm * 1e3, kBandHiUm * 1e3));
  return out;
}

FilterSet editedFilterSet(FilterSet set, const std::array<PassbandEdit, 3>& edits) {
  for (std::size_t c = 0; c < 3; ++c) set.channels[c] = editedPassband(set.channels[c], edits[c]);
  return set;
}

namespace {
constexpr double kHcOverKUmK = 14387.768775;  // hc/k in µm·K (CODATA 2018)
}

double ccmExtinction(double lambdaUm, double rv) {
  const double x = 1.0 / lambdaUm;
  if (!(x >= 0.3 && x <= 3.3) || !(rv > 0.0))
    throw Error(fmt::format("CCM extinction: 1/λ = {} µm⁻¹ is outside 0.3–3.3, or R_V = {} is not positive", x, rv));
  double a = 0.0, b = 0.0;
  if (x < 1.1) {  // infrared, Eq. 2
    a = 0.574 * std::pow(x, 1.61);
    b = -0.527 * std::pow(x, 1.61);
  } else {  // optical and near infrared, Eq. 3
    const double y = x - 1.82;
    const double ca[] = {1.0, 0.17699, -0.50447, -0.02427, 0.72085, 0.01979, -0.77530, 0.32999};
    const double cb[] = {0.0, 1.41338, 2.28305, 1.07233, -5.38434, -0.62251, 5.30260, -2.09002};
    double power = 1.0;
    for (int k = 0; k < 8; ++k, power *= y) {
      a += ca[k] * power;
      b += cb[k] * power;
    }
  }
  return a + b / rv;
}

double planck(double lambdaUm, double temperatureK) {
  return std::pow(lambdaUm, -5.0) / std::expm1(kHcOverKUmK / (lambdaUm * temperatureK));
}

double wienExponentUm(double temperatureK) { return kHcOverKUmK / temperatureK; }

double wien(double lambdaUm, double temperatureK) {
  return std::pow(lambdaUm, -5.0) * std::exp(-wienExponentUm(temperatureK) / lambdaUm);
}

PolynomialPiece greyScattering() {
  PolynomialPiece p{kBandLoUm, kBandHiUm, {}};
  p.coeffs[0] = 1.0;
  return p;
}

PolynomialPiece ccmScattering() {
  std::vector<double> lambdaUm, values;
  for (int i = 0; i <= 400; ++i) {
    lambdaUm.push_back(kBandLoUm + (kBandHiUm - kBandLoUm) * i / 400.0);
    values.push_back(ccmExtinction(lambdaUm.back()));
  }
  return fitPiecewisePolynomial(lambdaUm, values, kBandLoUm, kBandHiUm, 1, 3).pieces.front();
}

int degree(const PolynomialPiece& p) {
  for (int n = kMaxDegree; n > 0; --n)
    if (p.coeffs[static_cast<std::size_t>(n)] != 0.0) return n;
  return 0;
}

double StarSpectrum::at(double lambdaUm) const { return scattering.at(lambdaUm) * shape(lambdaUm); }

double StarSpectrum::shape(double lambdaUm) const {
  return normalisation * (model == StarModel::Planck ? planck(lambdaUm, temperatureK) : wien(lambdaUm, temperatureK));
}

StarSpectrum starShape(double temperatureK, StarModel model) {
  StarSpectrum s;
  s.temperatureK = temperatureK;
  s.model = model;
  std::vector<double> nodes, weights;
  gaussLegendre(48, kBandLoUm, kBandHiUm, nodes, weights);
  double integral = 0.0;
  for (std::size_t i = 0; i < nodes.size(); ++i) integral += weights[i] * s.shape(nodes[i]);
  s.normalisation = 1.0 / integral;
  return s;
}

StarSpectrum makeStarSpectrum(double temperatureK, StarModel model, const PolynomialPiece& scattering) {
  StarSpectrum s = starShape(temperatureK, model);
  s.scattering = scattering;
  std::vector<double> lambdaUm, values;
  for (int i = 0; i <= 400; ++i) {
    lambdaUm.push_back(kBandLoUm + (kBandHiUm - kBandLoUm) * i / 400.0);
    values.push_back(s.at(lambdaUm.back()));
  }
  // Fitted for relative error, since a cool star's light climbs through the band by orders of
  // magnitude (1 000 K: 10⁵×): two pieces fitted for absolute error missed its blue end by 2 %, as
  // the analytic method's image did. Pieces are added until the fit holds 1e-4, or 16 are used.
  for (int pieces = 2;; ++pieces) {
    s.fit = fitPiecewisePolynomial(lambdaUm, values, kBandLoUm, kBandHiUm, pieces, 5, /*relative=*/true);
    s.fitMaxRelativeError = 0.0;
    for (std::size_t i = 0; i < lambdaUm.size(); ++i)
      s.fitMaxRelativeError = std::max(s.fitMaxRelativeError, std::abs(s.fit.at(lambdaUm[i]) / values[i] - 1.0));
    if (s.fitMaxRelativeError <= 1e-4 || pieces == kMaxStarFitPieces) return s;
  }
}

std::vector<EmissionLine> readEmissionLines(const std::filesystem::path& csv) {
  CsvTable table = CsvTable::read(csv);
  int lambdaCol = table.column("wavelength_nm"), nameCol = table.column("line"), groupCol = table.column("group"),
      ratioCol = table.column("ratio");
  std::vector<EmissionLine> lines;
  for (const auto& row : table.rows())
    lines.push_back({row.fields[static_cast<std::size_t>(nameCol)], row.fields[static_cast<std::size_t>(groupCol)],
                     table.number(row, lambdaCol) * 1e-3, table.number(row, ratioCol)});
  return lines;
}

}  // namespace prism::nebula
