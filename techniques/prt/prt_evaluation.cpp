#include "techniques/prt/prt_evaluation.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include <fmt/format.h>

#include "core/error.h"
#include "core/json_schema.h"
#include "spectral/colour_checker.h"
#include "spectral/colour_difference.h"
#include "spectral/illuminant.h"
#include "spectral/sampling.h"

namespace prism::prt {
namespace {

// The SH of a function of the zenith angle only (about +z), projected once.
ShVector zonal(const std::function<double(double cosTheta)>& g) {
  return projectOnSh([&g](const glm::dvec3& dir) { return g(dir.z); });
}

shared::PrtReflectance reflectanceBlock(const Eigen::MatrixXd& columns) {  // 3 × n, n ≤ 16
  shared::PrtReflectance r;
  for (int j = 0; j < shared::kPrtMaxBasis; ++j) {
    r.r[j] = j < columns.cols() ? glm::vec3(static_cast<float>(columns(0, j)), static_cast<float>(columns(1, j)),
                                            static_cast<float>(columns(2, j)))
                                : glm::vec3(0.0f);
  }
  return r;
}

shared::PrtEnvironment environmentBlock(const Eigen::MatrixXd& rows) {  // n × 25, n ≤ 16
  shared::PrtEnvironment e;
  for (int j = 0; j < shared::kPrtMaxBasis; ++j) {
    for (int k = 0; k < 25; ++k) e.basis[j].c[k] = j < rows.rows() ? static_cast<float>(rows(j, k)) : 0.0f;
  }
  return e;
}

// The rows of an n × 3 matrix as vec3s.
std::vector<glm::vec3> nodeRows(const Eigen::MatrixXd& rows) {
  std::vector<glm::vec3> v;
  for (Eigen::Index q = 0; q < rows.rows(); ++q)
    v.emplace_back(static_cast<float>(rows(q, 0)), static_cast<float>(rows(q, 1)), static_cast<float>(rows(q, 2)));
  return v;
}

// XYZ per vertex for one projection, through the shared run-time sums.
void accumulate(const PrtObject& object, const std::vector<shared::Sh25>& transfer, const PrtProjection& projection,
                std::vector<Eigen::Vector3d>& xyz) {
  PRISM_CHECK(projection.basisCount >= 1 && projection.basisCount <= shared::kPrtMaxBasis);
  for (std::size_t v = 0; v < transfer.size(); ++v) {
    shared::PrtBasisIrradiance e = shared::prtVertexIrradiance(projection.environment, transfer[v], projection.basisCount);
    glm::vec3 c = shared::prtXyz(e, projection.reflectances[static_cast<std::size_t>(object.vertexMaterial[v])],
                                 projection.basisCount);
    xyz[v] += Eigen::Vector3d(c.x, c.y, c.z);
  }
}

void checkObject(const PrtObject& object, const std::vector<shared::Sh25>& transfer) {
  if (transfer.size() != object.mesh.positions.size() || object.vertexMaterial.size() != transfer.size())
    throw Error(fmt::format("PRT: {} transfer vectors and {} materials for {} vertices", transfer.size(),
                            object.vertexMaterial.size(), object.mesh.positions.size()));
  for (int m : object.vertexMaterial)
    if (m < 0 || m >= static_cast<int>(object.reflectances.size()))
      throw Error(fmt::format("PRT: material {} out of range ({} reflectances)", m, object.reflectances.size()));
}

}  // namespace

SpectralEnvironment uniformEnvironment(std::string name, const Spectrum& spd) {
  return {std::move(name), {{spd, zonal([](double) { return 1.0; })}}};
}

SpectralEnvironment skyGradientEnvironment(std::string name, const Spectrum& spd, double groundAlbedo) {
  return {std::move(name),
          {{spd, zonal([groundAlbedo](double z) { return skyGradient(z, groundAlbedo); })}}};
}

EquirectangularTexel equirectangularTexel(int x, int y, int width, int height) {
  const double pi = std::numbers::pi;
  double theta0 = pi * y / height, theta1 = pi * (y + 1) / height, theta = 0.5 * (theta0 + theta1);
  double phi = 2.0 * pi * (x + 0.5) / width;
  return {glm::dvec3(std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi), std::cos(theta)),
          2.0 * pi / width * (std::cos(theta0) - std::cos(theta1))};
}

ShVector equirectangularTexelSh(int x, int y, int width, int height) {
  const int s = std::max(1, (kTexelShCellsAcross + width - 1) / width);
  ShVector sum = ShVector::Zero();
  for (int j = 0; j < s; ++j)
    for (int i = 0; i < s; ++i) {
      const EquirectangularTexel cell = equirectangularTexel(x * s + i, y * s + j, width * s, height * s);
      sum += cell.solidAngle * evaluateSh(cell.direction);
    }
  return sum;
}

glm::ivec2 equirectangularTexelOf(const glm::dvec3& direction, int width, int height) {
  const double pi = std::numbers::pi;
  const glm::dvec3 d = glm::normalize(direction);
  const double theta = std::acos(std::clamp(d.z, -1.0, 1.0));
  double phi = std::atan2(d.y, d.x);
  if (phi < 0.0) phi += 2.0 * pi;
  return {std::min(width - 1, static_cast<int>(phi / (2.0 * pi) * width)),
          std::min(height - 1, static_cast<int>(theta / pi * height))};
}

std::vector<Eigen::VectorXd> termSpectra(const SpectralEnvironment& environment) {
  std::vector<Eigen::VectorXd> spectra;
  for (const EnvironmentTerm& t : environment.terms) spectra.push_back(sampleOnGrid(t.spectrum));
  return spectra;
}

SpectralEnvironment gridEnvironment(std::string name, const Eigen::MatrixXd& grid) {
  SpectralEnvironment environment{std::move(name), {}};
  for (int k = 0; k < 25; ++k) {
    Eigen::VectorXd column = grid.col(k);
    Spectrum s = Spectrum::fromFunction([&column](double lambdaNm) {
      double t = std::clamp((lambdaNm - kGridMinNm) / kGridStepNm, 0.0, kGridWavelengths - 1.0);
      int i = std::min(static_cast<int>(t), kGridWavelengths - 2);
      return (1.0 - (t - i)) * column[i] + (t - i) * column[i + 1];
    });
    environment.terms.push_back({s, ShVector::Unit(k)});
  }
  return environment;
}

SpectralEnvironment equirectangularEnvironment(std::string name, int width, int height,
                                               const std::vector<float>& linearRgb,
                                               const std::function<Spectrum(const glm::vec3& rgb)>& toSpectrum) {
  if (width < 1 || height < 1 || linearRgb.size() != 3 * static_cast<std::size_t>(width) * static_cast<std::size_t>(height))
    throw Error(fmt::format("{}: {} values for a {} × {} RGB map", name, linearRgb.size(), width, height));
  Eigen::MatrixXd grid = Eigen::MatrixXd::Zero(kGridWavelengths, 25);
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) {
      std::size_t at = 3 * (static_cast<std::size_t>(y) * static_cast<std::size_t>(width) + static_cast<std::size_t>(x));
      glm::vec3 rgb(linearRgb[at], linearRgb[at + 1], linearRgb[at + 2]);
      for (int c = 0; c < 3; ++c)
        if (!std::isfinite(rgb[c]) || rgb[c] < 0.0f || rgb[c] > schema::kFloatInputLimit)
          throw Error(fmt::format("{}: texel ({}, {}): channel {} is {}, not a radiance within 0..{:g}", name, x, y, c,
                                  rgb[c], schema::kFloatInputLimit));
      if (rgb == glm::vec3(0.0f)) continue;
      grid += sampleOnGrid(toSpectrum(rgb)) * equirectangularTexelSh(x, y, width, height).transpose();
    }
  }
  return gridEnvironment(std::move(name), grid);
}

SpectralEnvironment rotateEnvironment(const SpectralEnvironment& environment, const glm::dmat3& rotation) {
  ShRotation d = shRotation(rotation);
  SpectralEnvironment turned = environment;
  for (EnvironmentTerm& t : turned.terms) t.directional = d * t.directional;
  return turned;
}

Eigen::MatrixXd environmentOnGrid(const SpectralEnvironment& environment) {
  Eigen::MatrixXd grid = Eigen::MatrixXd::Zero(kGridWavelengths, 25);
  for (const EnvironmentTerm& t : environment.terms) grid += sampleOnGrid(t.spectrum) * t.directional.transpose();
  return grid;
}

PrtObject makeColourCheckerObject(int verticesPerPatch) {
  if (verticesPerPatch < 2) throw Error(fmt::format("PRT: {} vertices per patch (at least 2)", verticesPerPatch));
  const int columns = 6, rows = 4;
  const int nx = columns * (verticesPerPatch - 1) + 1, ny = rows * (verticesPerPatch - 1) + 1;
  const double step = 1.0 / (verticesPerPatch - 1), amplitude = 0.6, pi = std::numbers::pi;
  PrtObject object;
  for (int j = 0; j < ny; ++j) {
    for (int i = 0; i < nx; ++i) {
      double x = i * step, y = j * step;
      double sx = std::sin(pi * x), sy = std::sin(pi * y), cx = std::cos(pi * x), cy = std::cos(pi * y);
      double z = amplitude * sx * sx * sy * sy;
      // ∇z from the closed form: ∂z/∂x = 2π·A·sin x cos x sin² y (x, y in units of π).
      double dzdx = 2.0 * pi * amplitude * sx * cx * sy * sy, dzdy = 2.0 * pi * amplitude * sy * cy * sx * sx;
      object.mesh.positions.emplace_back(static_cast<float>(x), static_cast<float>(y), static_cast<float>(z));
      object.mesh.normals.push_back(glm::normalize(glm::vec3(static_cast<float>(-dzdx), static_cast<float>(-dzdy), 1.0f)));
      // Chart order: row 1 (dark skin …) at the top, i.e. the largest y.
      int column = std::min(static_cast<int>((i + 0.5) * step), columns - 1);
      int row = std::min(static_cast<int>((j + 0.5) * step), rows - 1);
      object.vertexMaterial.push_back((rows - 1 - row) * columns + column);
    }
  }
  for (int j = 0; j + 1 < ny; ++j) {
    for (int i = 0; i + 1 < nx; ++i) {
      auto at = [nx](int a, int b) { return static_cast<std::uint32_t>(b * nx + a); };
      object.mesh.indices.insert(object.mesh.indices.end(), {at(i, j), at(i + 1, j), at(i + 1, j + 1)});
      object.mesh.indices.insert(object.mesh.indices.end(), {at(i, j), at(i + 1, j + 1), at(i, j + 1)});
    }
  }
  for (const ColourCheckerPatch& p : colourChecker()) {
    object.reflectances.push_back(p.reflectance);
    object.materialNames.push_back(p.name);
  }
  return object;
}

PrtProjection projectSpectral(const std::vector<Spectrum>& reflectances, const Eigen::MatrixXd& environmentGrid,
                              const Observer& observer, const Eigen::MatrixXd& basis) {
  PRISM_CHECK(basis.rows() == kGridWavelengths && basis.cols() >= 1 && basis.cols() <= shared::kPrtMaxBasis);
  Eigen::MatrixXd cmf = observerOnGrid(observer);
  PrtProjection p;
  p.basisCount = static_cast<int>(basis.cols());
  p.environment = environmentBlock(basis.transpose() * environmentGrid);  // L̃ = Φᵀ L
  p.nodeWavelengthsNm = gridWavelengthsNm();  // a_qj = φ_j(λ_q), orthonormal on the grid
  p.nodeBasis = basis;
  for (const Spectrum& s : reflectances) {  // R̂ (3 × m): Σ_i φ_j(λ_i) f_r(λ_i) c̄(λ_i) · 5 nm
    Eigen::VectorXd rho = sampleOnGrid(s);
    const Eigen::MatrixXd rhoCmf = (cmf.array().colwise() * rho.array()).matrix() * kGridStepNm;  // 81 × 3
    p.reflectances.push_back(reflectanceBlock(rhoCmf.transpose() * basis));
    p.nodeReflectances.push_back(nodeRows(rhoCmf));
  }
  return p;
}

void requireRgbPrtObserver(const Observer& observer) {
  // RGB-PRT's colours are a colour space's, defined on CIE 1931 as the frame's RGB mode's are
  // (render/frame_settings.cpp): a camera's RGB went through xyzToRgb as if it were XYZ (a white
  // floor yellow through the Nikon D850).
  if (observer.name != "cie1931")
    throw Error(fmt::format("PRT's rgb-prt mode carries colours defined under CIE 1931, not spectra: the {} \"{}\" "
                            "needs prt.mode spectral or reference-5nm",
                            observer.isCamera ? "camera" : "observer", observer.name));
}

PrtProjection projectRgb(const std::vector<Spectrum>& reflectances, const Eigen::MatrixXd& environmentGrid,
                         const Observer& observer, const RgbColourSpace& space) {
  requireRgbPrtObserver(observer);
  Eigen::MatrixXd cmf = observerOnGrid(observer);
  PrtProjection p;
  p.basisCount = 3;
  // The environment's RGB per SH coefficient (3 × 25; linear, so per coefficient is exact).
  p.environment = environmentBlock(space.xyzToRgb * (cmf.transpose() * environmentGrid) * kGridStepNm);
  // A medium's T(λ) at the wavelengths R, G and B stand for, per channel.
  p.nodeWavelengthsNm.assign(kRgbStandInWavelengthsNm.begin(), kRgbStandInWavelengthsNm.end());
  p.nodeBasis = Eigen::MatrixXd::Identity(3, 3);
  // Albedos as an artist authors them: the reflectance's colour under CIE D65, the white of
  // sRGB, Display P3 and Rec.2020 (the spaces RGB-PRT is meant for).
  const Spectrum white = illuminant("D65");
  for (const Spectrum& s : reflectances) {  // R̂_c = albedo_c · (primary c's XYZ)
    Eigen::Vector3d albedo = space.xyzToRgb * reflectanceTristimulus(observer, s, white);
    const Eigen::Matrix3d block = space.rgbToXyz * albedo.asDiagonal();  // column c: R̂_c
    p.reflectances.push_back(reflectanceBlock(block));
    p.nodeReflectances.push_back(nodeRows(block.transpose()));
  }
  return p;
}

std::vector<PrtProjection> projectReference(const std::vector<Spectrum>& reflectances,
                                            const Eigen::MatrixXd& environmentGrid, const Observer& observer) {
  Eigen::MatrixXd cmf = observerOnGrid(observer);
  std::vector<PrtProjection> chunks;
  // 81 delta "basis functions" in chunks of 16: R̂_i = f_r(λ_i)·c̄(λ_i)·5 nm.
  for (int first = 0; first < kGridWavelengths; first += shared::kPrtMaxBasis) {
    PrtProjection& p = chunks.emplace_back();
    p.basisCount = std::min(shared::kPrtMaxBasis, kGridWavelengths - first);
    p.environment = environmentBlock(environmentGrid.middleRows(first, p.basisCount));
    for (int i = 0; i < p.basisCount; ++i) p.nodeWavelengthsNm.push_back(gridWavelengthNm(first + i));
    p.nodeBasis = Eigen::MatrixXd::Identity(p.basisCount, p.basisCount);
    for (const Spectrum& s : reflectances) {
      Eigen::VectorXd rho = sampleOnGrid(s).segment(first, p.basisCount);
      const Eigen::MatrixXd rhoCmf =
          (cmf.middleRows(first, p.basisCount).array().colwise() * rho.array()).matrix() * kGridStepNm;
      p.reflectances.push_back(reflectanceBlock(rhoCmf.transpose()));
      p.nodeReflectances.push_back(nodeRows(rhoCmf));
    }
  }
  return chunks;
}

std::vector<Eigen::Vector3d> shadeReference(const PrtObject& object, const std::vector<shared::Sh25>& transfer,
                                            const Eigen::MatrixXd& environmentGrid, const Observer& observer) {
  checkObject(object, transfer);
  std::vector<Eigen::Vector3d> xyz(transfer.size(), Eigen::Vector3d::Zero());
  for (const PrtProjection& chunk : projectReference(object.reflectances, environmentGrid, observer))
    accumulate(object, transfer, chunk, xyz);
  return xyz;
}

std::vector<Eigen::Vector3d> shadeSpectral(const PrtObject& object, const std::vector<shared::Sh25>& transfer,
                                           const Eigen::MatrixXd& environmentGrid, const Observer& observer,
                                           const Eigen::MatrixXd& basis) {
  checkObject(object, transfer);
  std::vector<Eigen::Vector3d> xyz(transfer.size(), Eigen::Vector3d::Zero());
  accumulate(object, transfer, projectSpectral(object.reflectances, environmentGrid, observer, basis), xyz);
  return xyz;
}

std::vector<Eigen::Vector3d> shadeRgb(const PrtObject& object, const std::vector<shared::Sh25>& transfer,
                                      const Eigen::MatrixXd& environmentGrid, const Observer& observer,
                                      const RgbColourSpace& space) {
  checkObject(object, transfer);
  std::vector<Eigen::Vector3d> xyz(transfer.size(), Eigen::Vector3d::Zero());
  accumulate(object, transfer, projectRgb(object.reflectances, environmentGrid, observer, space), xyz);
  return xyz;
}

Eigen::Vector3d sceneWhite(const Eigen::MatrixXd& environmentGrid, const Observer& observer) {
  PrtObject white;
  white.mesh.positions = {glm::vec3(0.0f)};
  white.mesh.normals = {glm::vec3(0.0f, 0.0f, 1.0f)};
  white.vertexMaterial = {0};
  white.reflectances = {Spectrum::constant(1.0)};
  return shadeReference(white, {shared::shClampedCosine(glm::vec3(0.0f, 0.0f, 1.0f))}, environmentGrid, observer)[0];
}

DeltaEStatistics compareShading(const std::vector<Eigen::Vector3d>& test, const std::vector<Eigen::Vector3d>& reference,
                                const Eigen::Vector3d& whiteXyz) {
  PRISM_CHECK(test.size() == reference.size() && !test.empty());
  DeltaEStatistics s;
  for (std::size_t v = 0; v < test.size(); ++v) {
    Eigen::Vector3d a = xyzToLab(test[v], whiteXyz), b = xyzToLab(reference[v], whiteXyz);
    double d94 = deltaE(a, b, DeltaEFormula::Cie94), d00 = deltaE(a, b, DeltaEFormula::Ciede2000);
    s.mean94 += d94;
    s.mean2000 += d00;
    s.max94 = std::max(s.max94, d94);
    s.max2000 = std::max(s.max2000, d00);
  }
  s.mean94 /= static_cast<double>(test.size());
  s.mean2000 /= static_cast<double>(test.size());
  return s;
}

std::vector<Eigen::Vector3d> displayColours(const std::vector<Eigen::Vector3d>& xyz, const Eigen::Vector3d& whiteXyz,
                                            const RgbColourSpace& space) {
  Eigen::Matrix3d adapt = chromaticAdaptation(Adaptation::Bradford, whiteXyz / whiteXyz.y(), space.whiteXyz());
  Eigen::Matrix3d toRgb = space.xyzToRgb * adapt / whiteXyz.y();
  std::vector<Eigen::Vector3d> rgb;
  rgb.reserve(xyz.size());
  for (const Eigen::Vector3d& c : xyz) rgb.push_back(space.encode((toRgb * c).cwiseMax(0.0).cwiseMin(1.0)));
  return rgb;
}

PrtReport basisSweep(const PrtObject& object, const std::vector<shared::Sh25>& transfer,
                     const SpectralEnvironment& environment, const Observer& observer, int maxBasis) {
  std::vector<Eigen::VectorXd> spectra;
  for (const Spectrum& s : object.reflectances) spectra.push_back(sampleOnGrid(s));
  SpectralBasis basis(spectra, {termSpectra(environment)});
  Eigen::MatrixXd grid = environmentOnGrid(environment);
  Eigen::Vector3d white = sceneWhite(grid, observer);
  std::vector<Eigen::Vector3d> reference = shadeReference(object, transfer, grid, observer);
  PrtReport report;
  report.vertices = transfer.size();
  int top = std::min({maxBasis, basis.available(), shared::kPrtMaxBasis});
  for (int m = 1; m <= top; ++m) {
    report.sweep.push_back({m, basis.capturedEnergy(m),
                            compareShading(shadeSpectral(object, transfer, grid, observer, basis.leading(m)), reference, white)});
  }
  report.rgbError = compareShading(shadeRgb(object, transfer, grid, observer, colourSpace("srgb")), reference, white);
  return report;
}

std::vector<DeltaEStatistics> metamerHalves(const PrtObject& object, const std::vector<shared::Sh25>& transfer,
                                            const Spectrum& a, const Spectrum& b,
                                            const std::vector<SpectralEnvironment>& environments,
                                            const Observer& observer, int maxBasis) {
  PrtObject first = object, second = object;
  first.reflectances = {a};
  second.reflectances = {b};
  first.vertexMaterial.assign(object.mesh.positions.size(), 0);
  second.vertexMaterial = first.vertexMaterial;
  std::vector<std::vector<Eigen::VectorXd>> lights;
  for (const SpectralEnvironment& e : environments) lights.push_back(termSpectra(e));
  SpectralBasis basis({sampleOnGrid(a), sampleOnGrid(b)}, lights);
  Eigen::MatrixXd phi = basis.leading(std::min({maxBasis, basis.available(), shared::kPrtMaxBasis}));
  std::vector<DeltaEStatistics> result;
  for (const SpectralEnvironment& e : environments) {
    Eigen::MatrixXd grid = environmentOnGrid(e);
    result.push_back(compareShading(shadeSpectral(second, transfer, grid, observer, phi),
                                    shadeSpectral(first, transfer, grid, observer, phi), sceneWhite(grid, observer)));
  }
  return result;
}

}  // namespace prism::prt
