// Ionisation zones: where in a nebula each emission-line group glows. Hot stars ionise the gas
// around them out to a front; species that take more energetic photons to make ([O III], He I)
// glow in an inner zone, low-ionisation species ([N II], [S II], [O II]) out to the front, neutral
// [O I] in the front's transition — the layering that gives the Hubble palette its blue cores and
// red rims. Without it every group glows wherever the density is.
//
// The model: nested Strömgren zones, each star alone. Photons above an energy E ionise the gas
// out to where the recombinations along the way use up the star's photons above E: along the ray
// from star s to a point p, the front lies where C_s(p) = ∫ ρ² r² dr (r from the star) reaches
// K·L_s·q(E, T_s), with
//   q(E, T)  the star's photons above E per unit of its luminosity in the band (380–780 nm, as
//            Prism normalises stars), by the star's own law (Planck's or Wien's), in closed form
//            (a series) over a band quadrature, relative to a Planck star's at 13.6 eV, 40 000 K;
//   K        R₀³/3, so that a star of luminosity 1 at 40 000 K in a uniform density 1 ionises
//            hydrogen out to the radius R₀ (the scene's front_radius, unit cube);
// and the gas there is ionised by a fraction f = 1 − smoothstep(1 − w, 1 + w, (C/(K·L·q))^⅓), w
// the front's relative width. Over stars the largest fraction holds. A group's zone is
//   f(max(E_make, 13.6 eV)) · (1 − f(E_destroy))
// with the ion's energies from data/nebula_ions.csv (NIST): made by photons above E_make, and
// glowing only where hydrogen is ionised (collisional lines need free electrons); ionised further
// above E_destroy. One recombination coefficient for all (the textbook approximation that makes
// the zones' radii scale with the cube root of the photon counts).
#pragma once

#include <filesystem>
#include <functional>
#include <limits>
#include <string>
#include <vector>

#include "techniques/nebula/nebula_density.h"
#include "techniques/nebula/nebula_spectra.h"

namespace prism::nebula {

struct NebulaStar;
struct NebulaPrecomputed;
struct VoxelField;

struct IonisationModel {
  double frontRadius = 0.3;  // R₀, unit cube (0, 4]
  double frontWidth = 0.1;   // w, relative (0, 0.5]
  bool operator==(const IonisationModel&) const = default;
};
inline constexpr double kMaxFrontRadius = 4.0, kMaxFrontWidth = 0.5;
inline constexpr double kHydrogenIonisationEv = 13.598434;

// An emitting ion of a line group (data/nebula_ions.csv): the energies that make it (0 for a
// neutral atom) and destroy it (infinity for none).
struct IonZone {
  std::string group;
  double makeEv = 0.0;
  double destroyEv = std::numeric_limits<double>::infinity();
};
std::vector<IonZone> readIonZones(const std::filesystem::path& csv);

// q(E, T) above: photons above E per unit band luminosity of a star at T by `model` (Planck's law
// or Wien's approximation, as the star's spectrum), relative to a Planck star at 13.6 eV, 40 000 K.
double ionisingPhotons(double energyEv, double temperatureK, StarModel model = StarModel::Planck);

// C_s(p) per voxel centre: ∫ ρ² r² dr along the segment from the star to the voxel, within the
// cube (r and the length in the cube's units).
VoxelField recombinationColumn(const DensityGrid& density, const NebulaStar& star, unsigned threads);

// Per voxel, the zone of each of `groups` (one value each, in order); Error naming a group that
// data/nebula_ions.csv lacks.
VoxelField ionisationZones(const DensityGrid& density, const std::vector<NebulaStar>& stars, StarModel starModel,
                           const std::vector<VoxelField>& columns, const IonisationModel& model,
                           const std::vector<std::string>& groups, unsigned threads);

// A renderer's zones (NebulaPrecomputed::lineZones, lineZone) for the model's ionisation and its
// lines, `lineGroups` the group of each of pre.lineLambdaUm: one zone per distinct group, in the
// order first seen. `tick` after each star's column.
void buildLineZones(NebulaPrecomputed& pre, const std::vector<std::string>& lineGroups, unsigned threads,
                    const std::function<void()>& tick);

}  // namespace prism::nebula
