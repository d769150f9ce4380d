#include "spectral/wavelength_fit.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iterator>
#include <limits>
#include <optional>
#include <sstream>
#include <string>
#include <utility>

#include <zlib.h>
#include <Eigen/Cholesky>

#include "core/atomic_file.h"
#include "core/cache_folder.h"
#include "core/error.h"
#include "core/fnv1a.h"
#include "core/parallel_for.h"
#include "spectral/colour_checker.h"
#include "spectral/colour_difference.h"
#include "spectral/rgb_intent.h"
#include "spectral/sampling.h"
#include "spectral/rgb_to_spectrum_cache.h"
#include "spectral/wavelength_pdf.h"

namespace prism {
namespace {

constexpr int kFitVersion = 7;  // 2: a checksum line; 3: fitWhite's floor; 4: dark nodes weigh 0; 5: the range's integral; 6: its ends; 7: the floor at 1 %

// A node where every light × reflectance is below this share of the brightest sample carries no
// light the renderer's floats hold (an LED at 830 nm, 1 nm wide, is e^−225 at 815 nm): its weights
// are 0, not the ±1e92 the least squares found, which were ∞ in float and made every pixel NaN.
constexpr double kDarkNode = 1e-12;
// Weights a fit never gives (its nodes are at least kDarkNode of the brightest): a cache entry
// holding one is damaged.
constexpr double kMaxWeight = 1e30;
constexpr int kMaxSweeps = 40;
constexpr double kFitWhiteFloor = 1e-2;  // fitWhite's, of Y
constexpr double kGridStepNm = 20.0;  // n = 4's exhaustive seed grid
constexpr int kFinalReweightings = 8;
constexpr double kReweightFloor = 0.05;  // ΔE00 below which a pair's weight stops growing
// CIELAB's scale of each channel's f(t): a* = 500·(fx − fy), L* = 116·fy, b* = 200·(fy − fz);
// fy enters all three, by √(116² + 500² + 200²).
constexpr double kChannelScale[3] = {500.0, 551.0, 200.0};

double labSlope(double t) {  // d f(t) / dt, f CIELAB's cube root with its linear toe
  constexpr double kToe = 216.0 / 24389.0;
  return t > kToe ? (1.0 / 3.0) * std::pow(t, -2.0 / 3.0) : 24389.0 / (27.0 * 116.0);
}

// The training set on the whole-nm nodes of the range, ready for evaluations.
class FitData {
 public:
  FitData(const WavelengthFitProblem& problem, const Observer& obs) {
    first_ = static_cast<int>(std::ceil(problem.minNm));
    nodes_ = static_cast<int>(std::floor(problem.maxNm)) - first_ + 1;
    // Per light, as the nodes sample it and as the truth integrates it: over the range alone, as
    // every other strategy's frame estimates it (a set fitted to the whole 360–830 nm from
    // wavelengths within 500–600 nm showed a white sphere white where the reference over that
    // band shows it green: 27.7 mean ΔE00 apart).
    std::vector<Spectrum> lights, bandedLights;
    for (const Spectrum& light : problem.lights) {
      Spectrum positive = light;
      for (int i = 0; i < kSpectrumSamples; ++i) positive[i] = std::max(0.0, positive[i]);
      const Spectrum banded = lightWithinRange(positive, problem.minNm, problem.maxNm);
      double y = obs.integrate(banded).y();
      if (!(y > 0.0)) continue;
      lights.push_back(positive * (1.0 / y));  // white Y = 1
      bandedLights.push_back(banded * (1.0 / y));
    }
    if (lights.empty()) throw Error("wavelength fit: no light the observer sees");
    const std::size_t pairs = lights.size() * problem.reflectances.size();
    samples_.resize(nodes_, static_cast<Eigen::Index>(pairs));
    truth_.resize(3, static_cast<Eigen::Index>(pairs));
    weight2_.resize(3, static_cast<Eigen::Index>(pairs));
    truthLab_.resize(3, static_cast<Eigen::Index>(pairs));
    white_.resize(3, static_cast<Eigen::Index>(pairs));
    Eigen::Index p = 0;
    for (std::size_t k = 0; k < lights.size(); ++k) {
      const Eigen::Vector3d white = fitWhite(bandedLights[k], obs);
      for (const Spectrum& reflectance : problem.reflectances) {
        const Spectrum radiance = lights[k] * reflectance;
        for (int i = 0; i < nodes_; ++i) samples_(i, p) = radiance[first_ - kLambdaMinNm + i];
        const Eigen::Vector3d xyz = obs.integrate(bandedLights[k] * reflectance);
        truth_.col(p) = xyz;
        white_.col(p) = white;
        truthLab_.col(p) = xyzToLab(xyz, white);
        for (int c = 0; c < 3; ++c) {
          const double w = kChannelScale[c] * labSlope(std::max(0.0, xyz[c]) / white[c]) / white[c];
          weight2_(c, p) = w * w;
        }
        ++p;
      }
    }
    emission_ = bandedLights.front();
    for (std::size_t k = 1; k < bandedLights.size(); ++k) emission_ += bandedLights[k];
    const double brightest = samples_.cwiseAbs().maxCoeff();
    for (int i = 0; i < nodes_; ++i)
      if (!(samples_.row(i).cwiseAbs().maxCoeff() >= kDarkNode * brightest)) samples_.row(i).setZero();
  }

  int first() const { return first_; }
  int nodes() const { return nodes_; }
  const Spectrum& emission() const { return emission_; }

  // The least-squares matrix for wavelengths at these nodes, and the mean ΔE00 it gives.
  double evaluate(const std::vector<int>& nodes, Eigen::Matrix<double, 3, Eigen::Dynamic>* weights = nullptr,
                  int reweightings = 0) const {
    const auto n = static_cast<Eigen::Index>(nodes.size());
    Eigen::MatrixXd s(n, samples_.cols());
    for (Eigen::Index i = 0; i < n; ++i) s.row(i) = samples_.row(nodes[static_cast<std::size_t>(i)]);
    Eigen::Matrix<double, 3, Eigen::Dynamic> m(3, n);
    Eigen::VectorXd pairWeight = Eigen::VectorXd::Ones(s.cols());
    Eigen::VectorXd errors(s.cols());
    for (int round = 0; round <= reweightings; ++round) {
      for (int c = 0; c < 3; ++c) {
        const Eigen::MatrixXd sw = s * (weight2_.row(c).transpose().cwiseProduct(pairWeight)).asDiagonal();
        Eigen::MatrixXd normal = sw * s.transpose();
        const Eigen::VectorXd rhs = sw * truth_.row(c).transpose();
        normal.diagonal().array() += 1e-12 * normal.trace() / static_cast<double>(n);
        m.row(c) = normal.ldlt().solve(rhs).transpose();
      }
      const Eigen::MatrixXd estimate = m * s;
      for (Eigen::Index p = 0; p < s.cols(); ++p)
        errors[p] = deltaE(xyzToLab(estimate.col(p), white_.col(p)), truthLab_.col(p), DeltaEFormula::Ciede2000);
      // Iteratively reweighted least squares towards the mean ΔE00 (an L1 norm), not its square.
      pairWeight = errors.cwiseMax(kReweightFloor).cwiseInverse();
    }
    if (weights) *weights = m;
    const double mean = errors.mean();
    return std::isfinite(mean) ? mean : std::numeric_limits<double>::infinity();  // NaN compares as no error
  }

 private:
  int first_ = 0;
  int nodes_ = 0;
  Eigen::MatrixXd samples_;  // nodes × pairs: light·reflectance at each whole nm (0 at dark nodes)
  Eigen::Matrix<double, 3, Eigen::Dynamic> truth_, weight2_, truthLab_, white_;
  Spectrum emission_;
};

// Strictly ascending nodes within [0, count): duplicates pushed apart.
std::vector<int> ascending(std::vector<int> nodes, int count) {
  std::sort(nodes.begin(), nodes.end());
  const int n = static_cast<int>(nodes.size());
  for (int i = 0; i < n; ++i) nodes[static_cast<std::size_t>(i)] = std::clamp(nodes[static_cast<std::size_t>(i)], i, count - n + i);
  for (int i = 1; i < n; ++i)
    nodes[static_cast<std::size_t>(i)] = std::max(nodes[static_cast<std::size_t>(i)], nodes[static_cast<std::size_t>(i - 1)] + 1);
  return nodes;
}

struct Candidate {
  std::vector<int> nodes;
  double error = std::numeric_limits<double>::infinity();
};

// Coordinate descent from `seed` (see the header).
Candidate descend(const FitData& data, std::vector<int> nodes, const std::function<void()>& tick) {
  double best = data.evaluate(nodes);
  const int n = static_cast<int>(nodes.size());
  for (int sweep = 0; sweep < kMaxSweeps; ++sweep) {
    bool improved = false;
    for (int i = 0; i < n; ++i) {
      const auto at = static_cast<std::size_t>(i);
      const int lo = i == 0 ? 0 : nodes[at - 1] + 1;
      const int hi = i == n - 1 ? data.nodes() - 1 : nodes[at + 1] - 1;
      std::vector<double> errors(static_cast<std::size_t>(hi - lo + 1), std::numeric_limits<double>::infinity());
      parallelFor(errors.size(), 0, [&](std::size_t k) {
        std::vector<int> trial = nodes;
        trial[at] = lo + static_cast<int>(k);
        if (trial[at] != nodes[at]) errors[k] = data.evaluate(trial);
      });
      const auto winner = std::min_element(errors.begin(), errors.end());
      if (*winner < best - 1e-12) {
        best = *winner;
        nodes[at] = lo + static_cast<int>(winner - errors.begin());
        improved = true;
      }
    }
    tick();
    if (!improved) break;
  }
  return {nodes, best};
}

// n = 4: the best combination of a 20 nm grid; none where the range holds fewer than n of its
// points (the other seeds start such a fit).
std::optional<std::vector<int>> gridSeed(const FitData& data, int n) {
  std::vector<int> grid;
  for (double offset = kGridStepNm / 2; offset < data.nodes(); offset += kGridStepNm)
    grid.push_back(static_cast<int>(offset));
  const int g = static_cast<int>(grid.size());
  if (g < n) return std::nullopt;
  std::vector<std::vector<int>> combinations;
  std::vector<int> index(static_cast<std::size_t>(n));
  for (int i = 0; i < n; ++i) index[static_cast<std::size_t>(i)] = i;
  while (true) {
    std::vector<int> nodes;
    for (int i : index) nodes.push_back(grid[static_cast<std::size_t>(i)]);
    combinations.push_back(nodes);
    int i = n - 1;
    while (i >= 0 && index[static_cast<std::size_t>(i)] == g - n + i) --i;
    if (i < 0) break;
    ++index[static_cast<std::size_t>(i)];
    for (int j = i + 1; j < n; ++j) index[static_cast<std::size_t>(j)] = index[static_cast<std::size_t>(j - 1)] + 1;
  }
  std::vector<double> errors(combinations.size());
  parallelFor(combinations.size(), 0, [&](std::size_t k) { errors[k] = data.evaluate(combinations[k]); });
  return combinations[static_cast<std::size_t>(std::min_element(errors.begin(), errors.end()) - errors.begin())];
}

void validateProblem(const WavelengthFitProblem& problem) {
  if (problem.count < 4 || problem.count > kMaxFittedWavelengths || problem.count % 4 != 0)
    throw Error("wavelength fit: count must be a multiple of 4 within 4–" + std::to_string(kMaxFittedWavelengths) +
                ", got " + std::to_string(problem.count));
  if (!(problem.minNm >= kLambdaMinNm && problem.maxNm <= kLambdaMaxNm && holdsWholeNanometres(problem.minNm, problem.maxNm, problem.count)))
    throw Error("wavelength fit: range must lie within 360–830 nm and hold a whole nm per wavelength");
  if (problem.lights.empty()) throw Error("wavelength fit: no light");
  if (problem.reflectances.empty()) throw Error("wavelength fit: no reflectance");
}

FittedWavelengths toSet(const FitData& data, const std::vector<int>& nodes) {
  FittedWavelengths set;
  data.evaluate(nodes, &set.weights, kFinalReweightings);
  for (int node : nodes) set.lambdaNm.push_back(data.first() + node);
  return set;
}

std::string serialise(const FittedWavelengths& set, std::uint64_t key) {
  std::ostringstream out;
  out.precision(17);
  out << "prism-wavelengths " << kFitVersion << "\nkey " << key << "\ncount " << set.lambdaNm.size() << "\nlambda";
  for (double lambda : set.lambdaNm) out << ' ' << lambda;
  for (int c = 0; c < 3; ++c) {
    out << "\nweights";
    for (Eigen::Index i = 0; i < set.weights.cols(); ++i) out << ' ' << set.weights(c, i);
  }
  out << '\n';
  std::string text = out.str();
  return text + "checksum " + std::to_string(fnv1a(text.data(), text.size())) + "\n";
}

// Null when the file is not a set of this key: another key or count, damaged (its checksum, the
// FNV-1a of the text before it, differs), or wavelengths not increasing within [minNm, maxNm]
// (an edited entry was used as it stood: λ 900 nm, two wavelengths swapped).
std::optional<FittedWavelengths> parse(const std::filesystem::path& path, std::uint64_t key, int count, double minNm,
                                       double maxNm) {
  std::ifstream file(path, std::ios::binary);
  const std::string text((std::istreambuf_iterator<char>(file)), std::istreambuf_iterator<char>());
  const std::size_t at = text.rfind("checksum ");
  if (at == std::string::npos || (at > 0 && text[at - 1] != '\n')) return std::nullopt;
  if (text.substr(at) != "checksum " + std::to_string(fnv1a(text.data(), at)) + "\n") return std::nullopt;
  std::istringstream in(text.substr(0, at));
  std::string word;
  int version = 0;
  std::uint64_t fileKey = 0;
  int fileCount = 0;
  if (!(in >> word >> version) || word != "prism-wavelengths" || version != kFitVersion) return std::nullopt;
  if (!(in >> word >> fileKey) || word != "key" || fileKey != key) return std::nullopt;
  if (!(in >> word >> fileCount) || word != "count" || fileCount != count) return std::nullopt;
  FittedWavelengths set;
  set.lambdaNm.resize(static_cast<std::size_t>(count));
  set.weights.resize(3, count);
  if (!(in >> word) || word != "lambda") return std::nullopt;
  double previous = -std::numeric_limits<double>::infinity();
  for (double& lambda : set.lambdaNm) {
    if (!(in >> lambda) || !(lambda > previous && lambda >= minNm && lambda <= maxNm)) return std::nullopt;
    previous = lambda;
  }
  for (int c = 0; c < 3; ++c) {
    if (!(in >> word) || word != "weights") return std::nullopt;
    for (int i = 0; i < count; ++i)
      if (!(in >> set.weights(c, i)) || !(std::abs(set.weights(c, i)) <= kMaxWeight)) return std::nullopt;
  }
  if (in >> word) return std::nullopt;  // nothing after the last weights
  return set;
}

void hashBytes(uLong& crc, const void* data, std::size_t size) {
  crc = crc32(crc, static_cast<const Bytef*>(data), static_cast<uInt>(size));
}

void hashSpectrum(uLong& crc, const Spectrum& s) {
  for (int i = 0; i < kSpectrumSamples; ++i) {
    const double v = s[i];
    hashBytes(crc, &v, sizeof v);
  }
}

}  // namespace

FittedWavelengths fitWavelengths(const WavelengthFitProblem& problem, const Observer& obs, const FitProgress& progress) {
  validateProblem(problem);
  const FitData data(problem, obs);
  const int n = problem.count;

  std::vector<std::vector<int>> seeds;
  std::vector<int> uniform, lights;
  const WavelengthPdf pdf = WavelengthPdf::lightsAndObserver(data.emission(), obs, problem.minNm, problem.maxNm);
  for (int i = 0; i < n; ++i) {
    const double u = (i + 0.5) / n;
    uniform.push_back(static_cast<int>(std::lround(problem.minNm + u * (problem.maxNm - problem.minNm))) - data.first());
    lights.push_back(static_cast<int>(std::lround(pdf.invert(u).lambdaNm)) - data.first());
  }
  seeds.push_back(ascending(uniform, data.nodes()));
  seeds.push_back(ascending(lights, data.nodes()));
  if (n == 4)
    if (auto grid = gridSeed(data, n)) seeds.push_back(std::move(*grid));

  const std::size_t total = seeds.size() * kMaxSweeps;
  std::size_t done = 0;
  auto tick = [&] {
    ++done;
    if (progress) progress(done, total);
  };
  Candidate best;
  for (const std::vector<int>& seed : seeds) {
    const std::size_t before = done;
    Candidate c = descend(data, seed, tick);
    done = before + kMaxSweeps;  // a seed that converges early skips its remaining sweeps
    if (progress) progress(done, total);
    if (c.error < best.error) best = c;
  }
  if (best.nodes.empty())
    throw Error("wavelength fit: no set of " + std::to_string(n) + " wavelengths gives a finite error under these lights");
  return toSet(data, best.nodes);
}

Spectrum lightWithinRange(const Spectrum& light, double minNm, double maxNm) {
  // w: each node's weight in ∫ over [minNm, maxNm] of the light's linear interpolation.
  std::vector<double> w(kSpectrumSamples, 0.0);
  for (int i = 0; i + 1 < kSpectrumSamples; ++i) {
    const double node = kLambdaMinNm + i;
    const double s = std::max(minNm, node) - node, t = std::min(maxNm, node + 1.0) - node;  // within [0, 1]
    if (!(t > s)) continue;
    w[static_cast<std::size_t>(i)] += (t - s) - 0.5 * (t * t - s * s);
    w[static_cast<std::size_t>(i + 1)] += 0.5 * (t * t - s * s);
  }
  Spectrum banded = light;
  for (int i = 0; i < kSpectrumSamples; ++i) {
    const double trapezoid = (i == 0 || i == kSpectrumSamples - 1) ? 0.5 : 1.0;  // Spectrum::integral's
    banded[i] = light[i] * w[static_cast<std::size_t>(i)] / trapezoid;
  }
  return banded;
}

Eigen::Vector3d fitWhite(const Spectrum& light, const Observer& obs) {
  const Eigen::Vector3d white = obs.integrate(light);
  return white.cwiseMax(kFitWhiteFloor * white.y());
}

FitError fitError(const FittedWavelengths& set, const WavelengthFitProblem& problem, const Observer& obs) {
  validateProblem(problem);
  FitError error;
  std::size_t count = 0;
  for (const Spectrum& light : problem.lights) {
    const Spectrum banded = lightWithinRange(light, problem.minNm, problem.maxNm);  // the truth's
    const Eigen::Vector3d white = fitWhite(banded, obs);
    if (white.y() <= 0.0) continue;
    for (const Spectrum& reflectance : problem.reflectances) {
      const Spectrum radiance = light * reflectance;
      Eigen::Vector3d estimate = Eigen::Vector3d::Zero();
      for (std::size_t i = 0; i < set.lambdaNm.size(); ++i)
        estimate += set.weights.col(static_cast<Eigen::Index>(i)) * radiance.at(set.lambdaNm[i]);
      const double e = deltaE(xyzToLab(estimate, white), xyzToLab(obs.integrate(banded * reflectance), white),
                              DeltaEFormula::Ciede2000);
      error.mean += e;
      error.max = std::max(error.max, e);
      ++count;
    }
  }
  error.mean /= static_cast<double>(std::max<std::size_t>(count, 1));
  return error;
}

std::vector<Spectrum> gamutReflectances(const RgbToSpectrumTable& table, int steps) {
  std::vector<Spectrum> out;
  for (int r = 0; r < steps; ++r)
    for (int g = 0; g < steps; ++g)
      for (int b = 0; b < steps; ++b) {
        const float d = static_cast<float>(steps - 1);
        out.push_back(RgbAlbedoSpectrum(table, {static_cast<float>(r) / d, static_cast<float>(g) / d,
                                                static_cast<float>(b) / d})
                          .toDense());
      }
  return out;
}

std::vector<Spectrum> standardTrainingReflectances(const RgbToSpectrumTable& table) {
  std::vector<Spectrum> out = colourCheckerReflectances();
  for (Spectrum& s : gamutReflectances(table, kFitGamutSteps)) out.push_back(std::move(s));
  return out;
}

std::uint64_t fitKey(const WavelengthFitProblem& problem, const Observer& obs) {
  uLong crc = crc32(0L, Z_NULL, 0);
  const int header[2] = {kFitVersion, problem.count};
  hashBytes(crc, header, sizeof header);
  const double range[2] = {problem.minNm, problem.maxNm};
  hashBytes(crc, range, sizeof range);
  uLong second = crc;  // a second, independent stream: 64 bits of key
  for (const Spectrum& s : problem.lights) hashSpectrum(crc, s);
  for (const Spectrum& s : problem.reflectances) hashSpectrum(crc, s);
  for (const Spectrum& s : obs.curves) hashSpectrum(crc, s);
  for (const Spectrum& s : obs.curves) hashSpectrum(second, s);
  for (const Spectrum& s : problem.reflectances) hashSpectrum(second, s);
  for (const Spectrum& s : problem.lights) hashSpectrum(second, s);
  return (static_cast<std::uint64_t>(crc) << 32) | static_cast<std::uint64_t>(second & 0xffffffffu);
}

FittedWavelengths cachedFitWavelengths(const WavelengthFitProblem& problem, const Observer& obs,
                                       const FitProgress& progress) {
  validateProblem(problem);
  const std::uint64_t key = fitKey(problem, obs);
  const std::filesystem::path path = cacheDirectory() / "wavelengths" / (std::to_string(key) + ".txt");
  std::error_code ec;
  requireNoFolderAtEntry(path, "a wavelength set");  // reading it would throw from the stream, not an Error
  if (std::filesystem::exists(path, ec)) {
    if (std::optional<FittedWavelengths> set = parse(path, key, problem.count, problem.minNm, problem.maxNm)) return *set;
    std::fprintf(stderr, "prism: cache entry %s is damaged (not a wavelength set of this key): refitting\n",
                 path.string().c_str());
  }
  std::filesystem::create_directories(path.parent_path(), ec);
  requireWritable(path);  // before the fit, not after
  FittedWavelengths set = fitWavelengths(problem, obs, progress);
  writeFileAtomically(path, serialise(set, key));
  return set;
}

}  // namespace prism
