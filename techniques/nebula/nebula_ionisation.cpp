#include "techniques/nebula/nebula_ionisation.h"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "core/csv.h"
#include "core/data_files.h"
#include "core/error.h"
#include "core/gauss_legendre.h"
#include "core/parallel_for.h"
#include "techniques/nebula/nebula_precomputed.h"

namespace prism::nebula {
namespace {

constexpr double kBoltzmannEvPerK = 8.617333262e-5;
constexpr double kPlanckTimesLightEvUm = 1.239841984;  // hc
constexpr double kReferenceTemperatureK = 40000.0;

// ∫_{x₀}^∞ x²/(eˣ − 1) dx = Σₙ e^(−n·x₀)·(x₀²/n + 2x₀/n² + 2/n³): a blackbody's photons above
// x₀ = E/kT, in units of (kT/h)³ up to a constant; Wien's law (x²e^(−x)) is the first term.
double photonsAbove(double x0, StarModel model) {
  double sum = 0.0;
  for (int n = 1; n < (model == StarModel::Wien ? 2 : 1000); ++n) {
    const double term = std::exp(-n * x0) * (x0 * x0 / n + 2.0 * x0 / (n * n) + 2.0 / (n * n * static_cast<double>(n)));
    sum += term;
    if (term < 1e-18 * sum) break;
  }
  return sum;
}

// ∫ x³/(eˣ − 1) dx over the band (x = hc/λkT; Wien's law: x³e^(−x)): its luminosity there, in
// units of (kT)⁴ up to the same constant.
double bandLuminosity(double temperatureK, StarModel model) {
  static const auto unit = [] {
    std::pair<std::vector<double>, std::vector<double>> nw;
    gaussLegendre(64, 0.0, 1.0, nw.first, nw.second);
    return nw;
  }();
  const double kt = kBoltzmannEvPerK * temperatureK;
  const double x0 = kPlanckTimesLightEvUm / (kBandHiUm * kt), x1 = kPlanckTimesLightEvUm / (kBandLoUm * kt);
  double sum = 0.0;
  for (std::size_t q = 0; q < unit.first.size(); ++q) {
    const double x = x0 + (x1 - x0) * unit.first[q];
    sum += (x1 - x0) * unit.second[q] * x * x * x / (model == StarModel::Wien ? std::exp(x) : std::expm1(x));
  }
  return sum;
}

double photonsPerBandLuminosity(double energyEv, double temperatureK, StarModel model) {
  const double kt = kBoltzmannEvPerK * temperatureK;
  return photonsAbove(energyEv / kt, model) / (kt * bandLuminosity(temperatureK, model));
}

double frontStep(double e0, double e1, double x) {  // smoothstep
  const double t = std::clamp((x - e0) / (e1 - e0), 0.0, 1.0);
  return t * t * (3.0 - 2.0 * t);
}

}  // namespace

std::vector<IonZone> readIonZones(const std::filesystem::path& csv) {
  CsvTable table = CsvTable::read(csv);
  const int groupCol = table.column("group"), makeCol = table.column("creation_ev"),
            destroyCol = table.column("destruction_ev");
  std::vector<IonZone> zones;
  for (const CsvRow& row : table.rows()) {
    IonZone z;
    z.group = row.fields[static_cast<std::size_t>(groupCol)];
    if (!row.fields[static_cast<std::size_t>(makeCol)].empty()) z.makeEv = table.number(row, makeCol);
    if (!row.fields[static_cast<std::size_t>(destroyCol)].empty()) z.destroyEv = table.number(row, destroyCol);
    if (!(z.makeEv >= 0.0 && z.destroyEv > z.makeEv))
      throw Error(fmt::format("{}:{}: an ion must be destroyed above the energy that makes it", table.path(), row.line));
    zones.push_back(std::move(z));
  }
  return zones;
}

double ionisingPhotons(double energyEv, double temperatureK, StarModel model) {
  static const double reference =
      photonsPerBandLuminosity(kHydrogenIonisationEv, kReferenceTemperatureK, StarModel::Planck);
  return photonsPerBandLuminosity(energyEv, temperatureK, model) / reference;
}

VoxelField recombinationColumn(const DensityGrid& density, const NebulaStar& star, unsigned threads) {
  VoxelField field{density.nx, density.ny, density.nz, 1,
                   std::vector<float>(static_cast<std::size_t>(density.nx) * density.ny * density.nz)};
  const double step = 0.5 / std::max({density.nx, density.ny, density.nz});
  parallelFor(static_cast<std::size_t>(density.nz), threads, [&](std::size_t k) {
    for (int j = 0; j < density.ny; ++j)
      for (int i = 0; i < density.nx; ++i) {
        const glm::dvec3 p((i + 0.5) / density.nx, (j + 0.5) / density.ny, (static_cast<double>(k) + 0.5) / density.nz);
        const glm::dvec3 d = star.position - p;
        const double length = glm::length(d);
        double column = 0.0;
        // The part of p + t·d, t ∈ [0, 1], inside the cube.
        double t0 = 0.0, t1 = 1.0;
        for (int a = 0; a < 3 && t1 > t0; ++a) {
          if (std::abs(d[a]) < 1e-15) continue;  // p is inside: the axis never leaves
          double lo = (0.0 - p[a]) / d[a], hi = (1.0 - p[a]) / d[a];
          if (lo > hi) std::swap(lo, hi);
          t0 = std::max(t0, lo);
          t1 = std::min(t1, hi);
        }
        if (length > 0.0 && t1 > t0) {
          const int n = std::max(1, static_cast<int>(std::ceil((t1 - t0) * length / step)));
          const double dt = (t1 - t0) / n;
          for (int s = 0; s < n; ++s) {
            const double t = t0 + (s + 0.5) * dt;
            const double rho = density.sample(p + d * t), r = (1.0 - t) * length;
            column += rho * rho * r * r;
          }
          column *= dt * length;
        }
        field.values[(k * static_cast<std::size_t>(density.ny) + static_cast<std::size_t>(j)) *
                         static_cast<std::size_t>(density.nx) + static_cast<std::size_t>(i)] = static_cast<float>(column);
      }
  });
  return field;
}

VoxelField ionisationZones(const DensityGrid& density, const std::vector<NebulaStar>& stars, StarModel starModel,
                           const std::vector<VoxelField>& columns, const IonisationModel& model,
                           const std::vector<std::string>& groups, unsigned threads) {
  PRISM_CHECK(columns.size() == stars.size());
  const std::vector<IonZone> table = readIonZones(dataFile("nebula_ions.csv"));
  std::vector<IonZone> zones;
  for (const std::string& g : groups) {
    const auto z = std::find_if(table.begin(), table.end(), [&](const IonZone& e) { return e.group == g; });
    if (z == table.end()) throw Error(fmt::format("nebula: no ionisation zone for the line group '{}' in nebula_ions.csv", g));
    zones.push_back(*z);
  }
  // Each star's photon budget K·L·q(E, T) for each zone's two energies (0: none).
  const double k = model.frontRadius * model.frontRadius * model.frontRadius / 3.0;
  const auto count = zones.size();
  std::vector<double> makeBudget(stars.size() * count), destroyBudget(stars.size() * count);
  for (std::size_t s = 0; s < stars.size(); ++s)
    for (std::size_t g = 0; g < count; ++g) {
      const double l = k * stars[s].luminosity;
      const double t = stars[s].temperatureK;
      makeBudget[s * count + g] = l * ionisingPhotons(std::max(zones[g].makeEv, kHydrogenIonisationEv), t, starModel);
      destroyBudget[s * count + g] =
          std::isfinite(zones[g].destroyEv) ? l * ionisingPhotons(zones[g].destroyEv, t, starModel) : 0.0;
    }
  const double w = model.frontWidth;
  auto ionised = [w](double column, double budget) {  // f: 1 inside the front, 0 beyond
    return budget > 0.0 ? 1.0 - frontStep(1.0 - w, 1.0 + w, std::cbrt(column / budget)) : 0.0;
  };
  const std::size_t slice = static_cast<std::size_t>(density.nx) * static_cast<std::size_t>(density.ny);
  VoxelField field{density.nx, density.ny, density.nz, static_cast<int>(count),
                   std::vector<float>(density.values.size() * count)};
  parallelFor(static_cast<std::size_t>(density.nz), threads, [&](std::size_t z) {
    for (std::size_t v = z * slice; v < (z + 1) * slice; ++v)
      for (std::size_t g = 0; g < count; ++g) {
        double made = 0.0, destroyed = 0.0;
        for (std::size_t s = 0; s < stars.size(); ++s) {
          const double c = columns[s].values[v];
          made = std::max(made, ionised(c, makeBudget[s * count + g]));
          destroyed = std::max(destroyed, ionised(c, destroyBudget[s * count + g]));
        }
        field.values[v * count + g] = static_cast<float>(made * (1.0 - destroyed));
      }
  });
  return field;
}

void buildLineZones(NebulaPrecomputed& pre, const std::vector<std::string>& lineGroups, unsigned threads,
                    const std::function<void()>& tick) {
  const NebulaModel& m = pre.model;
  PRISM_CHECK(m.ionisation && lineGroups.size() == pre.lineLambdaUm.size());
  std::vector<std::string> groups;
  pre.lineZone.clear();
  for (const std::string& g : lineGroups) {
    auto at = std::find(groups.begin(), groups.end(), g);
    if (at == groups.end()) at = groups.insert(groups.end(), g);
    pre.lineZone.push_back(static_cast<int>(at - groups.begin()));
  }
  std::vector<VoxelField> columns;
  for (const NebulaStar& star : m.stars) {
    columns.push_back(recombinationColumn(m.density, star, threads));
    if (tick) tick();
  }
  pre.lineZones = ionisationZones(m.density, m.stars, m.starModel, columns, *m.ionisation, groups, threads);
}

}  // namespace prism::nebula
