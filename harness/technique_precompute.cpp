#include "harness/technique_precompute.h"

#include <optional>
#include <string>

#include "harness/progress_bar.h"
#include "techniques/technique_pass.h"

namespace prism::harness {

void precomputeTechniques(const Scene& scene) {
  std::optional<ProgressBar> bar;
  std::string current;
  prism::precomputeTechniques(scene, [&](std::string_view what, std::size_t done, std::size_t total) {
    if (!bar || what != current) {
      current = what;
      bar.emplace(current);
    }
    bar->update(done, total);
  });
}

}  // namespace prism::harness
