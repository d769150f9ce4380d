#include "harness/validate_nebula.h"

#include <fmt/format.h>

#include "harness/nebula_display.h"
#include "techniques/nebula/gpu/nebula_gpu_marcher.h"
#include "techniques/nebula/nebula_scene.h"

namespace prism::harness {

std::vector<NebulaMethodDifference> runNebulaExperiment(const NebulaExperiment& experiment,
                                                        const std::filesystem::path& sceneDir, int size,
                                                        const std::filesystem::path& output,
                                                        const std::function<void()>& step) {
  nebula::NebulaScene scene = nebula::loadNebulaScene(sceneDir / (std::string(experiment.scene) + ".json"));
  scene.model.filters = experiment.filters;
  nebula::NebulaCamera& camera = scene.model.camera;
  if (camera.width > size || camera.height > size) nebula::scaleImage(camera, size);
  nebula::RenderSettings settings;
  settings.steps = scene.steps;
  const nebula::NebulaRenderer renderer(std::move(scene.model), settings);
  const bool palette = std::string(experiment.filters) == "hubble";
  const imaging::ColourMeaning meaning = palette ? imaging::ColourMeaning::LinearSrgb : imaging::ColourMeaning::Xyz;

  settings.method = nebula::Method::Reference;
  const nebula::NebulaImage reference = renderer.render(settings);
  const NebulaWhite white = nebulaWhiteLevels(reference, palette);
  const imaging::FloatImage referenceLinear = nebulaDisplayLinear(reference, white);
  nebulaDisplayPng(reference, palette, white).write(output / fmt::format("{}_reference.png", experiment.name));
  step();

  nebula::NebulaGpuMarcher marcher(renderer);
  std::vector<NebulaMethodDifference> differences;
  for (nebula::Method method : kNebulaMethods) {
    settings.method = method;
    const nebula::NebulaImage image = marcher.render(settings);
    const std::string mode = nebula::methodName(method);
    nebulaDisplayPng(image, palette, white).write(output / fmt::format("{}_{}.png", experiment.name, mode));
    const imaging::FloatImage linear = nebulaDisplayLinear(image, white);
    imaging::DifferenceOptions options;
    options.keepMap = true;
    differences.push_back({mode, imaging::compareImages(imaging::linearInput(referenceLinear, meaning),
                                                        imaging::linearInput(linear, meaning), options)});
    step();
  }
  return differences;
}

}  // namespace prism::harness
