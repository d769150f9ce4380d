#include "techniques/prt/prt_medium.h"

#include "core/error.h"

namespace prism::prt {

std::vector<Eigen::VectorXd> attenuatedSpectra(const std::vector<Eigen::VectorXd>& environment, const PrtMedium& medium) {
  const Eigen::VectorXd sigmaT = sampleOnGrid(medium.sigmaT), kd = sampleOnGrid(medium.kd);
  constexpr double kMetres[] = {0.0, 1.0, 2.0, 4.0, 8.0, 16.0, 32.0};
  std::vector<Eigen::VectorXd> spectra;
  for (const Eigen::VectorXd& e : environment) {
    PRISM_CHECK(e.size() == kGridWavelengths);
    for (double s : kMetres)
      for (double z : kMetres)
        if (s > 0.0 || z > 0.0) spectra.push_back(e.cwiseProduct((-(sigmaT * s + kd * z)).array().exp().matrix()));
  }
  return spectra;
}

std::vector<shared::PrtMediumNode> mediumNodes(const PrtProjection& projection, const PrtMedium* medium) {
  PRISM_CHECK(projection.nodeBasis.rows() == static_cast<Eigen::Index>(projection.nodeWavelengthsNm.size()) &&
              projection.nodeBasis.cols() == projection.basisCount);
  std::vector<shared::PrtMediumNode> nodes(projection.nodeWavelengthsNm.size());
  for (std::size_t q = 0; q < nodes.size(); ++q) {
    shared::PrtMediumNode& node = nodes[q];
    for (int j = 0; j < shared::kPrtMaxBasis; ++j)
      node.a[j / 4][j % 4] =
          j < projection.basisCount ? static_cast<float>(projection.nodeBasis(static_cast<Eigen::Index>(q), j)) : 0.0f;
    const double lambda = projection.nodeWavelengthsNm[q];
    node.coefficients = glm::vec4(medium ? static_cast<float>(medium->sigmaT.at(lambda)) : 0.0f,
                                  medium ? static_cast<float>(medium->kd.at(lambda)) : 0.0f, static_cast<float>(lambda), 0.0f);
  }
  return nodes;
}

glm::vec3 prtXyzThroughMedium(const shared::PrtBasisIrradiance& irradiance, const shared::PrtReflectance& reflectance,
                              int basisCount, const std::vector<shared::PrtMediumNode>& nodes,
                              const std::vector<glm::vec3>* nodeReflectances, const PrtMedium* medium,
                              const glm::vec3& camera, const glm::vec3& point, float nebulaDepthUm) {
  PRISM_CHECK(!nodeReflectances || nodeReflectances->size() == nodes.size());
  const float path = medium ? shared::prtMediumViewPath(camera, point, medium->boxMin, medium->boxMax) : 0.0f;
  const float depth = medium ? shared::prtMediumDepth(point, medium->boxMin, medium->boxMax) : 0.0f;
  if (path == 0.0f && depth == 0.0f && nebulaDepthUm <= 0.0f)
    return shared::prtShownXyz(shared::prtXyz(irradiance, reflectance, basisCount));  // as prt.frag
  glm::vec3 xyz(0.0f);
  for (std::size_t q = 0; q < nodes.size(); ++q) {
    const glm::vec3 rho = nodeReflectances ? (*nodeReflectances)[q] : shared::prtNodeReflectance(reflectance, basisCount, nodes[q]);
    xyz += shared::prtMediumTransmittance(nodes[q], path, depth, nebulaDepthUm) *
           shared::prtNodeIrradiance(irradiance, basisCount, nodes[q]) * rho;
  }
  return shared::prtShownXyz(xyz);
}

}  // namespace prism::prt
