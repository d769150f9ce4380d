#include "core/atomic_file.h"
#include "scene/scene.h"

namespace prism {

void requireNotSceneInput(const std::filesystem::path& output, const Scene& scene) {
  requireOtherFile(output, scene.file, "the scene file");
  for (const std::filesystem::path& file : scene.files) requireOtherFile(output, file, "a file the scene reads");
  for (const auto& section : scene.techniques.all())
    for (const std::filesystem::path& file : section->inputFiles()) requireOtherFile(output, file, "a file the scene reads");
}

}  // namespace prism
