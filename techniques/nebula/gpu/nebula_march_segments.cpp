#include "techniques/nebula/gpu/nebula_march_segments.h"

#include <fmt/format.h>

#include <algorithm>

#include "core/error.h"

namespace prism::nebula {

long marchLoopIterations(const MarchLoopCost& cost, int steps, int items) {
  const long s = steps, n = cost.itemsMarchSteps ? std::max(items, 1) : items;  // a march without groups still marches
  return cost.fixed + (cost.itemsMarchSteps ? n * s * (cost.perStep + cost.perItem) : s * (cost.perStep + n * cost.perItem));
}

std::vector<MarchSegment> planMarchSegments(const MarchLoopCost& cost, int steps, int items, long budget) {
  if (steps < 1) throw Error("nebula: a march needs at least one step");
  if (marchLoopIterations(cost, 1, std::min(items, 1)) > budget)
    throw Error(fmt::format("nebula: one step of one star takes up to {} shader loop iterations, past this GPU driver's "
                            "{}; march on the CPU",
                            marchLoopIterations(cost, 1, std::min(items, 1)), budget));
  // As many items as one step allows, then as many steps as those items allow.
  int itemsPer = items;
  while (itemsPer > 1 && marchLoopIterations(cost, 1, itemsPer) > budget) itemsPer = (itemsPer + 1) / 2;
  const auto fits = [&](int count) { return marchLoopIterations(cost, count, itemsPer) <= budget; };
  int stepsPer = 1;
  while (stepsPer < steps && fits(std::min(steps, 2 * stepsPer))) stepsPer = std::min(steps, 2 * stepsPer);
  // Bisect between the last fitting and the first failing doubling.
  for (int hi = std::min(steps, 2 * stepsPer); hi - stepsPer > 1;) {
    const int mid = stepsPer + (hi - stepsPer) / 2;
    (fits(mid) ? stepsPer : hi) = mid;
  }
  std::vector<MarchSegment> segments;
  for (int s = 0; s < steps; s += stepsPer)
    for (int i = 0; i < std::max(items, 1); i += std::max(itemsPer, 1))
      segments.push_back({s, std::min(steps, s + stepsPer), i, std::min(items, i + itemsPer)});
  return segments;
}

}  // namespace prism::nebula
