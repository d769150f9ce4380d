// Observers: three spectral sensitivities that turn a spectrum into a tristimulus value. The CIE
// standard observers give XYZ; a camera gives its own raw RGB (each camera's curves on their
// source's scale, see data/SOURCES.md).
//
// Names: "cie1931" (2°, 1931), "cie1964" (10°, 1964), and every camera in data/cameras.csv by its
// name there (e.g. "nikon_d850", "Nikon 5100 (NPL)"). Camera curves are zero outside their
// measured band (Extrapolation::Zero).
#pragma once

#include <array>
#include <string>
#include <string_view>
#include <vector>

#include <Eigen/Core>

#include "spectral/spectrum.h"

namespace prism {

struct Observer {
  std::string name;
  bool isCamera = false;
  std::array<Spectrum, 3> curves;  // x̄ ȳ z̄, or camera r g b

  // ∫ s(λ)·curve(λ) dλ for the three curves (trapezoid at 1 nm, spectrum unit × nm).
  Eigen::Vector3d integrate(const Spectrum& s) const;
  // The three curves at one wavelength (linear between 1 nm nodes).
  Eigen::Vector3d at(double lambdaNm) const;
};

// Error naming the observer when unknown.
const Observer& observer(std::string_view name);
// CIE 1931 without a name lookup, for code that runs every frame (frame data, the forward pass):
// the colour spaces' XYZ is its, so many computations want it whatever the chosen observer is.
const Observer& cie1931Observer();
std::vector<std::string> listObservers();
std::vector<std::string> listCameras();

// The colour of a spectrum under an illuminant, normalised so that a perfect white reflector
// has Y (or camera G) = 1: ∫ R·S·c̄ / ∫ S·ȳ.
Eigen::Vector3d reflectanceTristimulus(const Observer& obs, const Spectrum& reflectance,
                                       const Spectrum& illuminant);
// The same observer's white: reflectanceTristimulus of a constant 1.
Eigen::Vector3d whiteTristimulus(const Observer& obs, const Spectrum& illuminant);

// reflectanceTristimulus as weights per 1 nm node: Σ_i w[i]·R[i] equals it for any reflectance
// R, so optimisers can evaluate colours without building a Spectrum; Σ_i w[i] is the white.
std::vector<Eigen::Vector3d> reflectanceWeights(const Observer& obs, const Spectrum& illuminant);

// The factor that makes a renderer's tristimulus absolute: 683 lm/W (so that CIE Y of spectral
// radiance in W·sr⁻¹·m⁻²·nm⁻¹ is luminance in cd/m²), and for a camera also the scale that gives
// its green of D65 the Y of D65 (raw camera RGB on the luminance scale; its fitted camera matrix
// does the rest). Every renderer multiplies its integration weights by it.
double absoluteTristimulusScale(const Observer& obs);

// 683 lm/W · ∫ S(λ) ȳ(λ) dλ over 360–830 nm (CIE 1931 ȳ, trapezoid at 1 nm): the luminous
// quantity of one unit of S (luminance in cd/m² when S is radiance in W·sr⁻¹·m⁻²·nm⁻¹). A scene's
// lights are divided by it on load, light colours and the background scaled by it.
double luminousIntegral(const Spectrum& spd);
// 683 lm/W · the CIE 1931 XYZ of S (Y is luminousIntegral's): how RGB renderers carry a light, as
// their colour space's xyzToRgb of it.
Eigen::Vector3d luminousTristimulus(const Spectrum& spd);

}  // namespace prism
