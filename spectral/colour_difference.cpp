#include "spectral/colour_difference.h"

#include <string>

#include "shared_cpp.h"
#include "core/error.h"

namespace prism::shared {
#include "cielab.glsl"
}

namespace prism {
namespace {

glm::vec3 toVec3(const Eigen::Vector3d& v) {
  return {static_cast<float>(v.x()), static_cast<float>(v.y()), static_cast<float>(v.z())};
}

Eigen::Vector3d toEigen(const glm::vec3& v) { return {v.x, v.y, v.z}; }

}  // namespace

DeltaEFormula deltaEFormulaFromName(std::string_view name) {
  if (name == "76") return DeltaEFormula::Cie76;
  if (name == "94") return DeltaEFormula::Cie94;
  if (name == "2000") return DeltaEFormula::Ciede2000;
  throw Error("unknown colour-difference formula '" + std::string(name) + "' (known: 76, 94, 2000)");
}

// In double, cielab.glsl's floor: a float rounding would move the whites by 1e-7.
Eigen::Vector3d labWhite(const Eigen::Vector3d& whiteXyz) {
  return whiteXyz.cwiseMax(static_cast<double>(shared::kLabWhiteFloor) * whiteXyz.y());
}

Eigen::Vector3d xyzToLab(const Eigen::Vector3d& xyz, const Eigen::Vector3d& whiteXyz) {
  return toEigen(shared::xyzToLab(toVec3(xyz), toVec3(whiteXyz)));
}

Eigen::Vector3d labToXyz(const Eigen::Vector3d& lab, const Eigen::Vector3d& whiteXyz) {
  return toEigen(shared::labToXyz(toVec3(lab), toVec3(whiteXyz)));
}

double deltaE(const Eigen::Vector3d& lab1, const Eigen::Vector3d& lab2, DeltaEFormula formula) {
  switch (formula) {
    case DeltaEFormula::Cie76: return shared::deltaE76(toVec3(lab1), toVec3(lab2));
    case DeltaEFormula::Cie94: return shared::deltaE94(toVec3(lab1), toVec3(lab2));
    case DeltaEFormula::Ciede2000: return shared::deltaE2000(toVec3(lab1), toVec3(lab2));
  }
  return 0.0;
}

}  // namespace prism
