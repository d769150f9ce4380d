#include "techniques/nebula/nebula_render.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <mutex>
#include <numbers>

#include <Eigen/Dense>
#include <fmt/format.h>

#include "core/data_files.h"
#include "core/error.h"
#include "core/gauss_legendre.h"
#include "core/parallel_for.h"
#include "core/worst_of.h"
#include "techniques/nebula/nebula_integrals.h"
#include "techniques/nebula/nebula_precomputed.h"

namespace prism::nebula {

NebulaViewFrame viewFrame(const NebulaCamera& camera) {
  NebulaViewFrame f;
  f.forward = glm::normalize(camera.target - camera.position);
  glm::dvec3 side = glm::cross(f.forward, glm::dvec3(0, 1, 0));
  if (glm::length(side) < 1e-9) side = glm::cross(f.forward, glm::dvec3(0, 0, 1));
  f.right = glm::normalize(side);
  f.up = glm::cross(f.right, f.forward);
  return f;
}

void scaleImage(NebulaCamera& camera, int pixels) {
  const double scale = static_cast<double>(pixels) / std::max(camera.width, camera.height);
  camera.width = std::max(1, static_cast<int>(std::lround(camera.width * scale)));
  camera.height = std::max(1, static_cast<int>(std::lround(camera.height * scale)));
}

const char* methodName(Method m) {
  switch (m) {
    case Method::Reference: return "reference";
    case Method::Analytic: return "analytic";
    case Method::Projection: return "projection";
    case Method::LightDensity: return "light-density";
    case Method::PreIntegration: return "pre-integration";
  }
  return "?";
}

Method methodFromName(std::string_view name) {
  for (Method m : {Method::Reference, Method::Analytic, Method::Projection, Method::LightDensity, Method::PreIntegration})
    if (name == methodName(m)) return m;
  throw Error(fmt::format("unknown nebula method '{}' (reference, analytic, projection, light-density, pre-integration)", excerpt(name)));
}

namespace {

constexpr double kPi = std::numbers::pi;
constexpr int kLightNodes = 48;  // Gauss–Legendre nodes over the band for the 2D basis's projections


}  // namespace

namespace {

// ∫ f over each piece of a passband by Gauss–Legendre (16 nodes per piece).
template <class F>
double integratePassband(const Passband& band, F f) {
  static const auto unit = [] {  // on [0, 1], mapped onto each piece
    std::pair<std::vector<double>, std::vector<double>> nw;
    gaussLegendre(16, 0.0, 1.0, nw.first, nw.second);
    return nw;
  }();
  double sum = 0.0;
  for (const auto& piece : band.response.pieces) {
    double width = piece.lambda1Um - piece.lambda0Um;
    for (std::size_t q = 0; q < unit.first.size(); ++q) {
      double l = piece.lambda0Um + width * unit.first[q];
      sum += width * unit.second[q] * piece.at(l) * f(l);
    }
  }
  return sum;
}

VoxelField opticalDepthToStar(const DensityGrid& density, const NebulaStar& star, double extinction,
                              unsigned threads) {
  VoxelField field{density.nx, density.ny, density.nz, 1,
                   std::vector<float>(static_cast<std::size_t>(density.nx) * density.ny * density.nz)};
  double step = 0.5 / std::max({density.nx, density.ny, density.nz});
  parallelFor(static_cast<std::size_t>(density.nz), threads, [&](std::size_t k) {
    for (int j = 0; j < density.ny; ++j)
      for (int i = 0; i < density.nx; ++i) {
        glm::dvec3 p((i + 0.5) / density.nx, (j + 0.5) / density.ny, (static_cast<double>(k) + 0.5) / density.nz);
        glm::dvec3 d = star.position - p;
        double length = glm::length(d), t0 = 0.0, t1 = 0.0, column = 0.0;
        if (length > 0.0 && shared::f64::nebulaClipToCube(p, d, 1.0, t0, t1)) {  // up to the star
          double segment = (t1 - t0) * length;
          int n = std::max(1, static_cast<int>(std::ceil(segment / step)));
          double dt = (t1 - t0) / n;
          for (int s = 0; s < n; ++s) column += density.sample(p + d * (t0 + (s + 0.5) * dt));
          column *= dt * length;
        }
        field.values[(k * static_cast<std::size_t>(density.ny) + static_cast<std::size_t>(j)) *
                         static_cast<std::size_t>(density.nx) + static_cast<std::size_t>(i)] =
            static_cast<float>(kCtUm * extinction * column);
      }
  });
  return field;
}

// What the filters change (NebulaPrecomputed says which fields): the set itself, the lines'
// responses, the analytic pieces, projection's and light–density's finishing weights; the
// pre-integration tables are built at their first render.
void applyFilters(NebulaPrecomputed& pre) {
  const NebulaModel& m = pre.model;
  pre.filters = editedFilterSet(filterSet(m.filters), m.passbands);
  pre.lineResponse.clear();
  pre.projectionWeights.clear();
  for (std::size_t l = 0; l < pre.lineLambdaUm.size(); ++l) {
    glm::dvec3 r;
    for (int c = 0; c < 3; ++c) r[c] = pre.filters.channels[static_cast<std::size_t>(c)].response.at(pre.lineLambdaUm[l]) * pre.lineWeight[l];
    pre.lineResponse.push_back(r);
  }
  pre.analytic = makeAnalyticPieces(pre.filters, pre.spectra);
  const auto card = static_cast<int>(pre.basis.a.size());
  for (std::size_t st = 0; st < pre.spectra.size(); ++st) {
    std::array<std::array<double, 8>, 3> w{};
    for (std::size_t c = 0; c < 3; ++c)
      for (int k = 0; k < card; ++k)
        w[c][static_cast<std::size_t>(k)] =
            integratePassband(pre.filters.channels[c], [&](double l) { return pre.spectra[st].at(l) * pre.basis.at(k, l); });
    pre.projectionWeights.push_back(w);
  }
  if (pre.lightCount > 0) {
    const int kCount = pre.lightCount;
    // U(c, k, m) = ∫ P_S,c fₖ bₘ dλ.
    pre.lightU.assign(static_cast<std::size_t>(3 * kCount * 8), 0.0);
    for (int c = 0; c < 3; ++c)
      for (int k = 0; k < kCount; ++k)
        for (int mm = 0; mm < card; ++mm)
          pre.lightU[static_cast<std::size_t>((c * kCount + k) * 8 + mm)] =
              integratePassband(pre.filters.channels[static_cast<std::size_t>(c)], [&](double l) { return pre.lightFunction(k, l) * pre.basis.at(mm, l); });
  }
}

}  // namespace

void validate(const RenderSettings& s) {
  auto within = [](std::string_view what, int v, int lo, int hi) {
    if (v < lo || v > hi) throw Error(fmt::format("nebula: {} {} is not within {}..{}", what, v, lo, hi));
  };
  within("steps", s.steps, 1, kMaxSteps);
  within("basis size", s.basisSize, 1, kMaxBasisSize);
  within("light basis size", s.lightBasisSize, 1, kMaxLightBasisSize);
  within("reference intervals", s.referenceIntervals, 2, kMaxReferenceIntervals);
  if (s.referenceIntervals % 2) throw Error(fmt::format("nebula: reference intervals {} is odd (Simpson's rule)", s.referenceIntervals));
  if (s.uniformSamples != 0) within("reference samples", s.uniformSamples, 2, kMaxUniformSamples);
  if (!(s.basisMaxDepthUm > 0.0 && s.basisMaxDepthUm <= kMaxBasisDepthUm))
    throw Error(fmt::format("nebula: basis depth {:g} µm is not within (0, {:g}]", s.basisMaxDepthUm, kMaxBasisDepthUm));
}

NebulaRenderer::NebulaRenderer(NebulaModel model, const RenderSettings& s,
                               const std::function<void(std::size_t, std::size_t)>& progress)
    : mPre(std::make_unique<NebulaPrecomputed>()) {
  NebulaPrecomputed& pre = *mPre;
  pre.model = std::move(model);
  const NebulaModel& m = pre.model;
  if (m.density.values.empty()) throw Error("nebula: no density");
  validate(s);
  // Emission lines: weight = the group's strength × the line's ratio within it.
  std::vector<std::string> lineGroups;
  for (const auto& line : readEmissionLines(dataFile("nebula_lines.csv"))) {
    double strength = 0.0;
    for (const auto& g : m.lineGroups)
      if (g.group == line.group) strength = g.strength;
    if (strength == 0.0) continue;
    pre.lineLambdaUm.push_back(line.lambdaUm);
    pre.lineWeight.push_back(strength * line.ratio);
    lineGroups.push_back(line.group);
  }
  const bool zoned = m.ionisation && !lineGroups.empty();
  std::size_t stages = m.stars.size() * (zoned ? 2 : 1) + 2, done = 0;
  auto tick = [&] {
    if (progress) progress(++done, stages);
  };
  for (const auto& star : m.stars) {
    pre.spectra.push_back(makeStarSpectrum(star.temperatureK, m.starModel, m.scatteringSpectrum));
    pre.starDepth.push_back(opticalDepthToStar(m.density, star, m.extinction, s.threads));
    tick();
  }
  if (zoned) buildLineZones(pre, lineGroups, s.threads, tick);
  // Projection: the 1D basis on the band and each star's filter integrals of it.
  const double exponentMaxUm = std::max(2.0, s.basisMaxDepthUm);
  pre.basis = findExpBasis(kBandLoUm, kBandHiUm, s.basisMaxDepthUm, exponentMaxUm, s.basisSize, s.basisSpacingUm);
  auto card = static_cast<int>(pre.basis.a.size());
  for (int j = 0; j < card; ++j) (j < 4 ? pre.basisLo[j] : pre.basisHi[j - 4]) = static_cast<float>(pre.basis.a[static_cast<std::size_t>(j)]);
  auto coefficientsAt = [&pre](double x) {
    std::array<double, 8> raw{}, coefficients{};
    glm::dvec4 lo = shared::f64::nebulaExpMoments(x, pre.exponents(0), kBandLoUm, kBandHiUm);
    glm::dvec4 hi = shared::f64::nebulaExpMoments(x, pre.exponents(1), kBandLoUm, kBandHiUm);
    for (int j = 0; j < 4; ++j) raw[static_cast<std::size_t>(j)] = lo[j], raw[static_cast<std::size_t>(j + 4)] = hi[j];
    pre.toCoefficients(raw, coefficients);
    return coefficients;
  };
  auto push = [&pre](const std::array<double, 8>& c) {
    pre.moments.lo.emplace_back(c[0], c[1], c[2], c[3]);
    pre.moments.hi.emplace_back(c[4], c[5], c[6], c[7]);
  };
  // The entry before 0, which Catmull–Rom's tangent at 0 reads, by cubic extrapolation: the
  // exponential integrals take no negative depth, and mirroring c(h) there would make the slope
  // at 0 vanish (1e-3 off over the first interval, the front of every cloud).
  std::array<std::array<double, 8>, 4> first{};
  for (int e = 0; e < 4; ++e) first[static_cast<std::size_t>(e)] = coefficientsAt(e * pre.moments.step);
  std::array<double, 8> before{};
  for (std::size_t k = 0; k < 8; ++k) before[k] = 4.0 * first[0][k] - 6.0 * first[1][k] + 4.0 * first[2][k] - first[3][k];
  push(before);
  for (int e = 0; e <= kMomentTableSize + 1; ++e) push(coefficientsAt(e * pre.moments.step));
  tick();
  // Light–density: the 2D basis over the stars' temperature range.
  if (!m.stars.empty()) {
    double tMin = 1e30, tMax = 0.0;
    for (const auto& st : m.stars) tMin = std::min(tMin, st.temperatureK), tMax = std::max(tMax, st.temperatureK);
    StarSpectrum s0 = makeStarSpectrum(tMin, m.starModel, m.scatteringSpectrum),
                 s1 = makeStarSpectrum(tMax, m.starModel, m.scatteringSpectrum);
    std::vector<double> nodes, weights;
    gaussLegendre(kLightNodes, kBandLoUm, kBandHiUm, nodes, weights);
    const int aCount = 41, tCount = 5, gCount = 24, familyTemps = tMax > tMin ? 8 : 1;
    const double aMax = exponentMaxUm;
    // The family's stars, once each (their spectra, not their fits P_L: the basis is fitted to
    // the light itself).
    std::vector<StarSpectrum> familyStars;
    for (int t = 0; t < familyTemps; ++t) {
      familyStars.push_back(starShape(familyTemps == 1 ? tMin : tMin * std::pow(tMax / tMin, t / (familyTemps - 1.0)),
                                      m.starModel));
      familyStars.back().scattering = m.scatteringSpectrum;
    }
    Eigen::MatrixXd family(kLightNodes, gCount * familyTemps), candidates(kLightNodes, aCount * tCount);
    for (int q = 0; q < kLightNodes; ++q) {
      double l = nodes[static_cast<std::size_t>(q)];
      for (int t = 0; t < familyTemps; ++t) {
        const double light = familyStars[static_cast<std::size_t>(t)].at(l);
        for (int g = 0; g < gCount; ++g) family(q, t * gCount + g) = light * std::exp(-s.basisMaxDepthUm * g / (gCount - 1) / l);
      }
      for (int t = 0; t < tCount; ++t)
        for (int a = 0; a < aCount; ++a) {
          double mix = t / (tCount - 1.0);
          candidates(q, t * aCount + a) = ((1 - mix) * s0.at(l) + mix * s1.at(l)) * std::exp(-aMax * a / (aCount - 1) / l);
        }
    }
    Eigen::Map<Eigen::VectorXd> wq(weights.data(), kLightNodes);
    // Conditioning: a candidate must add a new direction of at least 1e-4 of its norm (the Gram
    // matrix then stays within double's reach: its Cholesky pivots are ≥ 1e-8 relative).
    pre.lightGreedy = greedyBasis(family, candidates, wq, s.lightBasisSize, {}, {}, 0.0, 1e-4);
    pre.lightCount = static_cast<int>(pre.lightGreedy.chosen.size());
    int kCount = pre.lightCount;
    // Orthonormal fₖ = Σⱼ M2(k,j)·rawⱼ by the Cholesky factor of the raw Gram matrix (256 nodes).
    auto raw = [chosen = pre.lightGreedy.chosen, s0, s1, aMax](int j, double l) {
      int c = chosen[static_cast<std::size_t>(j)];
      int t = c / aCount, a = c % aCount;
      double mix = t / (tCount - 1.0);
      return ((1 - mix) * s0.at(l) + mix * s1.at(l)) * std::exp(-aMax * a / (aCount - 1) / l);
    };
    std::vector<double> fineNodes, fineWeights;
    gaussLegendre(256, kBandLoUm, kBandHiUm, fineNodes, fineWeights);
    Eigen::MatrixXd gram = Eigen::MatrixXd::Zero(kCount, kCount);
    for (std::size_t q = 0; q < fineNodes.size(); ++q)
      for (int i = 0; i < kCount; ++i)
        for (int j = 0; j < kCount; ++j) gram(i, j) += fineWeights[q] * raw(i, fineNodes[q]) * raw(j, fineNodes[q]);
    Eigen::LLT<Eigen::MatrixXd> llt(gram);
    if (llt.info() != Eigen::Success) throw Error("nebula: the light basis's Gram matrix is singular in double");
    Eigen::MatrixXd lower = llt.matrixL();
    Eigen::MatrixXd m2 = lower.triangularView<Eigen::Lower>().solve(Eigen::MatrixXd::Identity(kCount, kCount));
    // fₖ, kept for the finish's weights U (applyFilters).
    pre.lightFunction = [raw, m2](int k, double l) {
      double v = 0.0;
      for (int j = 0; j <= k; ++j) v += m2(k, j) * raw(j, l);
      return v;
    };
    const std::function<double(int, double)>& f = pre.lightFunction;
    // Per voxel: dₖ = Σ_s σ₁L_s/(16π²d²)·⟨S_s e^(−g_s/λ), fₖ⟩ (Gauss–Legendre, 48 nodes).
    std::vector<double> fAtNodes(static_cast<std::size_t>(kCount * kLightNodes));
    for (int k = 0; k < kCount; ++k)
      for (int q = 0; q < kLightNodes; ++q)
        fAtNodes[static_cast<std::size_t>(k * kLightNodes + q)] = weights[static_cast<std::size_t>(q)] * f(k, nodes[static_cast<std::size_t>(q)]);
    std::vector<std::vector<double>> spectraAtNodes;
    for (const auto& sp : pre.spectra) {
      std::vector<double> v;
      for (double l : nodes) v.push_back(sp.at(l));
      spectraAtNodes.push_back(v);
    }
    const DensityGrid& dg = m.density;
    VoxelField& lc = pre.lightCoefficients;
    lc = {dg.nx, dg.ny, dg.nz, kCount, std::vector<float>(static_cast<std::size_t>(dg.nx) * dg.ny * dg.nz * kCount)};
    parallelFor(static_cast<std::size_t>(dg.nz), s.threads, [&](std::size_t k) {
      std::vector<double> light(kLightNodes);
      for (int j = 0; j < dg.ny; ++j)
        for (int i = 0; i < dg.nx; ++i) {
          std::size_t voxel = (k * static_cast<std::size_t>(dg.ny) + static_cast<std::size_t>(j)) * static_cast<std::size_t>(dg.nx) + static_cast<std::size_t>(i);
          glm::dvec3 p((i + 0.5) / dg.nx, (j + 0.5) / dg.ny, (static_cast<double>(k) + 0.5) / dg.nz);
          std::fill(light.begin(), light.end(), 0.0);
          for (std::size_t st = 0; st < m.stars.size(); ++st) {
            double w = shared::f64::nebulaStarWeight(m.scattering, m.stars[st].luminosity,
                                                     glm::dot(m.stars[st].position - p, m.stars[st].position - p));
            double g = pre.starDepth[st].values[voxel];
            for (int q = 0; q < kLightNodes; ++q)
              light[static_cast<std::size_t>(q)] += w * spectraAtNodes[st][static_cast<std::size_t>(q)] * std::exp(-g / nodes[static_cast<std::size_t>(q)]);
          }
          for (int kk = 0; kk < kCount; ++kk) {
            double dk = 0.0;
            for (int q = 0; q < kLightNodes; ++q) dk += fAtNodes[static_cast<std::size_t>(kk * kLightNodes + q)] * light[static_cast<std::size_t>(q)];
            lc.values[voxel * static_cast<std::size_t>(kCount) + static_cast<std::size_t>(kk)] = static_cast<float>(dk);
          }
        }
    });
  }
  applyFilters(pre);
  tick();
}

NebulaRenderer::NebulaRenderer(const NebulaRenderer& volume, const std::string& filters,
                               const std::array<PassbandEdit, 3>& passbands)
    : mPre(std::make_unique<NebulaPrecomputed>()) {
  const NebulaPrecomputed& from = *volume.mPre;
  NebulaPrecomputed& pre = *mPre;
  pre.model = from.model;
  pre.model.filters = filters;
  pre.model.passbands = passbands;
  pre.spectra = from.spectra;
  pre.starDepth = from.starDepth;
  pre.lineLambdaUm = from.lineLambdaUm;
  pre.lineWeight = from.lineWeight;
  pre.lineZones = from.lineZones;
  pre.lineZone = from.lineZone;
  pre.basis = from.basis;
  pre.basisLo = from.basisLo;
  pre.basisHi = from.basisHi;
  pre.moments = from.moments;
  pre.lightGreedy = from.lightGreedy;
  pre.lightCoefficients = from.lightCoefficients;
  pre.lightCount = from.lightCount;
  pre.lightFunction = from.lightFunction;
  applyFilters(pre);
}

NebulaRenderer::~NebulaRenderer() = default;
const ExpBasis& NebulaRenderer::basis() const { return mPre->basis; }
const GreedyResult& NebulaRenderer::lightBasis() const { return mPre->lightGreedy; }
const NebulaModel& NebulaRenderer::model() const { return mPre->model; }
const NebulaPrecomputed& NebulaRenderer::precomputed() const { return *mPre; }

namespace {
void buildPreIntegration(NebulaPrecomputed& pre) {
  for (std::size_t st = 0; st < pre.spectra.size(); ++st) {
    MomentTable table;
    table.size = 4096;
    table.step = kMomentTableMaxUm / (table.size - 1);
    for (int e = -1; e <= table.size + 1; ++e) {
      double x = e * table.step;  // before 0 too: e^(+step/λ) is as smooth
      glm::dvec4 v(0.0);
      for (std::size_t c = 0; c < 3; ++c)
        v[static_cast<int>(c)] = integratePassband(pre.filters.channels[c], [&](double l) { return pre.spectra[st].at(l) * std::exp(-x / l); });
      table.lo.push_back(glm::vec4(v));
      table.hi.push_back(glm::vec4(0.0f));
    }
    pre.preIntegrated.push_back(std::move(table));
  }
}
}  // namespace

void NebulaRenderer::preparePreIntegration() const {
  std::call_once(mPre->preIntegratedOnce, [this] { buildPreIntegration(*mPre); });
}

NebulaRenderer::ReferenceNodes NebulaRenderer::referenceNodes(const RenderSettings& s) const {
  const NebulaPrecomputed& pre = *mPre;
  validate(s);
  const std::size_t starCount = pre.model.stars.size();
  ReferenceNodes nodes;
  auto& refLambda = nodes.lambdaUm;
  auto& refWeight = nodes.weights;
  refWeight.resize(starCount);
  for (std::size_t c = 0; c < 3; ++c) {
    const Passband& band = pre.filters.channels[c];
    std::vector<double> w;
    if (s.uniformSamples > 0) {
      const int n = s.uniformSamples;
      double a = band.response.lambdaMinUm(), b = band.response.lambdaMaxUm(), h = (b - a) / (n - 1);
      for (int i = 0; i < n; ++i) {
        double l = a + h * i;
        refLambda[c].push_back(l);
        w.push_back((i == 0 || i == n - 1 ? 0.5 : 1.0) * h * band.response.at(l));
      }
    } else {
      for (const auto& piece : band.response.pieces) {
        int n = s.referenceIntervals;
        double h = (piece.lambda1Um - piece.lambda0Um) / n;
        for (int i = 0; i <= n; ++i) {
          double l = piece.lambda0Um + h * i;
          refLambda[c].push_back(l);
          w.push_back((i == 0 || i == n ? 1.0 : (i % 2 ? 4.0 : 2.0)) * h / 3.0 * piece.at(l));
        }
      }
    }
    for (std::size_t st = 0; st < starCount; ++st) {
      std::vector<double> ws(w.size());
      for (std::size_t i = 0; i < w.size(); ++i) ws[i] = w[i] * pre.spectra[st].at(refLambda[c][i]);
      refWeight[st][c] = std::move(ws);
    }
  }
  return nodes;
}

NebulaImage NebulaRenderer::render(const RenderSettings& s,
                                   const std::function<void(std::size_t, std::size_t)>& progress) const {
  const NebulaPrecomputed& pre = *mPre;
  if (s.method == Method::PreIntegration) preparePreIntegration();
  const NebulaModel& m = pre.model;
  validate(s);
  if (!s.rayLimits.empty() && s.rayLimits.size() != static_cast<std::size_t>(m.camera.width) * static_cast<std::size_t>(m.camera.height))
    throw Error("nebula: ray limits must be one a pixel");
  const int card = static_cast<int>(pre.basis.a.size());
  if (s.basisSize != card && (s.method == Method::Projection || s.method == Method::LightDensity))
    throw Error(fmt::format("nebula: the renderer was built for a basis of {} elements, not {}", card, s.basisSize));
  const std::size_t starCount = m.stars.size();
  const float l0 = static_cast<float>(kBandLoUm), l1 = static_cast<float>(kBandHiUm);

  ReferenceNodes reference;
  if (s.method == Method::Reference) reference = referenceNodes(s);
  const auto& refLambda = reference.lambdaUm;
  const auto& refWeight = reference.weights;

  const NebulaCamera& cam = m.camera;
  const NebulaViewFrame frame = viewFrame(cam);  // named, not bound: clang 14 cannot capture a binding
  const glm::dvec3 forward = frame.forward, right = frame.right, up = frame.up;
  double tanHalf = std::tan(cam.fovYDeg * kPi / 360.0), aspect = static_cast<double>(cam.width) / cam.height;

  // The coefficients cₖ(x) of e^(−x/λ) on the orthonormal basis: from the table (float), or
  // Σⱼ M(k,j)·mⱼ(x) over the raw moments' closed form (double, or float beyond the table).
  auto coefficientsAt = [&](double x) {
    std::array<double, 8> raw{}, c{};
    glm::vec4 tLo, tHi;
    if (!s.doublePrecision && s.momentTable && pre.moments.lookup(x, tLo, tHi, card > 4)) {
      for (int j = 0; j < 4; ++j) c[static_cast<std::size_t>(j)] = tLo[j], c[static_cast<std::size_t>(j + 4)] = card > 4 ? tHi[j] : 0.0f;
      return c;
    }
    glm::dvec4 mLo, mHi(0.0);
    if (s.doublePrecision) {
      mLo = shared::f64::nebulaExpMoments(x, pre.exponents(0), kBandLoUm, kBandHiUm);
      if (card > 4) mHi = shared::f64::nebulaExpMoments(x, pre.exponents(1), kBandLoUm, kBandHiUm);
    } else {
      mLo = shared::nebulaExpMoments(static_cast<float>(x), pre.basisLo, l0, l1);
      if (card > 4) mHi = shared::nebulaExpMoments(static_cast<float>(x), pre.basisHi, l0, l1);
    }
    for (int j = 0; j < 4; ++j) raw[static_cast<std::size_t>(j)] = mLo[j], raw[static_cast<std::size_t>(j + 4)] = mHi[j];
    pre.toCoefficients(raw, c);
    return c;
  };
  NebulaImage image{cam.width, cam.height, std::vector<glm::vec3>(static_cast<std::size_t>(cam.width) * cam.height)};
  parallelFor(static_cast<std::size_t>(cam.height), s.threads, [&](std::size_t row) {
    std::vector<float> depths(starCount), lightD(static_cast<std::size_t>(std::max(pre.lightCount, 1))),
        zones(static_cast<std::size_t>(pre.lineZones.width));
    std::vector<double> moments(starCount * 8), lightAcc(static_cast<std::size_t>(std::max(pre.lightCount, 1)) * 8);
    for (int px = 0; px < cam.width; ++px) {
      double u = (2.0 * (px + 0.5) / cam.width - 1.0) * tanHalf * aspect;
      double v = (1.0 - 2.0 * (static_cast<double>(row) + 0.5) / cam.height) * tanHalf;
      glm::dvec3 dir = glm::normalize(forward + u * right + v * up);
      double t0 = 0.0, t1 = 0.0;
      glm::dvec3 colour(0.0);
      std::fill(moments.begin(), moments.end(), 0.0f);
      std::fill(lightAcc.begin(), lightAcc.end(), 0.0f);
      if (shared::f64::nebulaClipToCube(cam.position, dir, 1e30, t0, t1)) {
        double dt = (t1 - t0) / s.steps, gCam = 0.0;
        const double tLimit = s.rayLimits.empty() ? 1e30 : s.rayLimits[row * static_cast<std::size_t>(cam.width) + static_cast<std::size_t>(px)];
        for (int i = 0; i < s.steps; ++i) {
          const double t = t0 + (i + 0.5) * dt;
          if (t > tLimit) break;  // behind a surface
          glm::dvec3 p = cam.position + dir * t;
          if (shared::f64::nebulaRayOpaque(gCam)) break;
          double rho = m.density.sample(p);
          if (rho <= 0.0) continue;
          double dg = kCtUm * m.extinction * rho * dt;
          double g = gCam + 0.5 * dg;  // the sample sees half of its own step's extinction
          gCam += dg;
          if (s.emissionLines) {
            if (!pre.lineZone.empty()) pre.lineZones.sample(p, zones.data());
            for (std::size_t l = 0; l < pre.lineLambdaUm.size(); ++l)
              colour += m.emission * rho * dt * (pre.lineZone.empty() ? 1.0 : zones[static_cast<std::size_t>(pre.lineZone[l])]) *
                        shared::f64::nebulaAttenuation(g, pre.lineLambdaUm[l]) * pre.lineResponse[l];
          }
          if (s.method == Method::LightDensity) {
            if (pre.lightCount == 0) continue;
            pre.lightCoefficients.sample(p, lightD.data());
            const std::array<double, 8> cg = coefficientsAt(g);
            double w = rho * dt;
            for (int k = 0; k < pre.lightCount; ++k)
              for (int j = 0; j < card; ++j)
                lightAcc[static_cast<std::size_t>(k * 8 + j)] += w * lightD[static_cast<std::size_t>(k)] * cg[static_cast<std::size_t>(j)];
            continue;
          }
          for (std::size_t st = 0; st < starCount; ++st) {
            float gs = 0.0f;
            pre.starDepth[st].sample(p, &gs);
            glm::dvec3 toStar = m.stars[st].position - p;
            double w = shared::f64::nebulaStarWeight(m.scattering * rho * dt, m.stars[st].luminosity, glm::dot(toStar, toStar));
            double x = g + gs;
            switch (s.method) {
              case Method::Reference:
                for (std::size_t c = 0; c < 3; ++c) {
                  double sum = 0.0;
                  const auto& lambdas = refLambda[c];
                  const auto& weights = refWeight[st][c];
                  for (std::size_t n = 0; n < lambdas.size(); ++n) sum += weights[n] * std::exp(-x / lambdas[n]);
                  colour[static_cast<int>(c)] += w * sum;
                }
                break;
              case Method::Analytic: {
                const double wienB = pre.analytic.wienExponentUm[st];
                for (std::size_t c = 0; c < 3; ++c) {
                  double sum = 0.0;
                  if (s.doublePrecision)
                    for (const auto& piece : pre.analytic.f64[st][c])
                      sum += shared::f64::nebulaAnalyticPieceIntegral(piece, x + wienB, wienB > 0.0);
                  else
                    for (const auto& piece : pre.analytic.f32[st][c])
                      sum += shared::nebulaAnalyticPieceIntegral(piece, static_cast<float>(x + wienB), wienB > 0.0);
                  colour[static_cast<int>(c)] += w * sum;
                }
                break;
              }
              case Method::Projection: {
                const std::array<double, 8> cx = coefficientsAt(x);
                for (int j = 0; j < card; ++j) moments[st * 8 + static_cast<std::size_t>(j)] += w * cx[static_cast<std::size_t>(j)];
                break;
              }
              case Method::PreIntegration: {
                glm::vec4 table, unused;
                if (pre.preIntegrated[st].lookup(x, table, unused, false)) {
                  colour += w * glm::dvec3(table.x, table.y, table.z);
                } else {  // beyond the table (x > 16 µm: e^(−x/λ) < 1e-9 over the band)
                  for (std::size_t c = 0; c < 3; ++c)
                    colour[static_cast<int>(c)] += w * integratePassband(pre.filters.channels[c], [&](double l) { return pre.spectra[st].at(l) * std::exp(-x / l); });
                }
                break;
              }
              case Method::LightDensity: break;
            }
          }
        }
      }
      // Finishing the pixel: card(B) filter integrals per star (projection) or per 2D element.
      if (s.method == Method::Projection)
        for (std::size_t st = 0; st < starCount; ++st)
          for (std::size_t c = 0; c < 3; ++c)
            for (int j = 0; j < card; ++j)
              colour[static_cast<int>(c)] += pre.projectionWeights[st][c][static_cast<std::size_t>(j)] * moments[st * 8 + static_cast<std::size_t>(j)];
      if (s.method == Method::LightDensity)
        for (int c = 0; c < 3; ++c)
          for (int k = 0; k < pre.lightCount; ++k)
            for (int j = 0; j < card; ++j)
              colour[c] += pre.lightU[static_cast<std::size_t>((c * pre.lightCount + k) * 8 + j)] * lightAcc[static_cast<std::size_t>(k * 8 + j)];
      image.pixels[row * static_cast<std::size_t>(cam.width) + static_cast<std::size_t>(px)] = glm::vec3(colour);
    }
  }, progress);
  return image;
}

double maxRelativeError(const NebulaImage& image, const NebulaImage& reference, double floorOfMax) {
  PRISM_CHECK(image.pixels.size() == reference.pixels.size());
  double worst = 0.0;
  bool compared = false;
  for (int c = 0; c < 3; ++c) {
    double peak = 0.0;
    for (const auto& p : reference.pixels) peak = std::max(peak, static_cast<double>(p[c]));
    for (std::size_t i = 0; i < reference.pixels.size(); ++i) {
      double r = reference.pixels[i][c];
      if (!std::isfinite(r) || !std::isfinite(image.pixels[i][c])) return std::numeric_limits<double>::infinity();
      if (r <= 0.0 || r < floorOfMax * peak) continue;
      worst = worstOf(worst, std::abs(image.pixels[i][c] - r) / r);
      compared = true;
    }
  }
  return compared ? worst : std::numeric_limits<double>::quiet_NaN();
}

}  // namespace prism::nebula
