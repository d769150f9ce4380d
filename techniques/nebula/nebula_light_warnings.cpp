#include "techniques/nebula/nebula_light_warnings.h"

#include <algorithm>

#include <fmt/format.h>

#include "techniques/nebula/nebula_precomputed.h"

namespace prism::nebula {

std::string unlitLinesWarning(const NebulaModel& model) {
  const bool lit = std::any_of(model.stars.begin(), model.stars.end(), [](const NebulaStar& s) { return s.luminosity > 0.0; });
  const bool lines = std::any_of(model.lineGroups.begin(), model.lineGroups.end(),
                                 [](const LineGroupStrength& g) { return g.strength > 0.0; });
  if (!model.ionisation || model.emission <= 0.0 || !lines || lit) return "";
  return "ionisation zones without a star (of luminosity above 0) to ionise the gas: no emission line glows; "
         "without \"ionisation\" the lines glow wherever the density is";
}

std::string darkNebulaWarning(const NebulaRenderer& renderer) {
  const NebulaModel& m = renderer.model();
  if (!unlitLinesWarning(m).empty()) return "";
  const NebulaPrecomputed& pre = renderer.precomputed();
  const bool litStar = std::any_of(m.stars.begin(), m.stars.end(), [](const NebulaStar& s) { return s.luminosity > 0.0; });
  if (m.scattering > 0.0 && litStar) return "";
  bool strongLine = false, seenLine = false;
  for (std::size_t l = 0; l < pre.lineWeight.size(); ++l) {
    if (!(pre.lineWeight[l] > 0.0)) continue;
    strongLine = true;
    seenLine = seenLine || glm::any(glm::greaterThan(pre.lineResponse[l], glm::dvec3(0.0)));
  }
  if (m.emission > 0.0 && seenLine) return "";
  const std::string scatter = m.stars.empty() ? "no star to scatter the light of"
                              : !litStar      ? "no star of luminosity above 0 to scatter the light of"
                                              : "scattering 0, which scatters no star's light";
  const std::string glow = !(m.emission > 0.0) ? "emission 0"
                           : !strongLine       ? "no emission line of strength above 0"
                                               : fmt::format("emission lines only outside every passband of the {} filters", m.filters);
  return fmt::format("the nebula gives no light, it only dims what lies behind it (its own image is black): {}, and {}",
                     scatter, glow);
}

}  // namespace prism::nebula
