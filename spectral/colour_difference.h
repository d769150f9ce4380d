// CIELAB and colour differences on the CPU, through the same code the GPU runs
// (shaders/shared/cielab.glsl, single precision).
#pragma once

#include <string_view>

#include <Eigen/Core>

namespace prism {

enum class DeltaEFormula { Cie76, Cie94, Ciede2000 };
DeltaEFormula deltaEFormulaFromName(std::string_view name);  // "76" | "94" | "2000"

// The white CIELAB divides by: each channel at least 1e-6 of its Y (cielab.glsl's labWhite).
Eigen::Vector3d labWhite(const Eigen::Vector3d& whiteXyz);

// xyz and whiteXyz on the same scale.
Eigen::Vector3d xyzToLab(const Eigen::Vector3d& xyz, const Eigen::Vector3d& whiteXyz);
Eigen::Vector3d labToXyz(const Eigen::Vector3d& lab, const Eigen::Vector3d& whiteXyz);
double deltaE(const Eigen::Vector3d& lab1, const Eigen::Vector3d& lab2,
              DeltaEFormula formula = DeltaEFormula::Ciede2000);

}  // namespace prism
