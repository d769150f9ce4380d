#include "render/frame_context.h"

#include "scene/scene_emission.h"

namespace prism::render {

FrameContext frameContext(const FrameSettings& settings, const Scene& scene, const RgbToSpectrumTable& table,
                          std::optional<std::shared_ptr<const Spectrum>> environmentFromAbove,
                          std::shared_ptr<const WavelengthSampler> wavelengths) {
  FrameContext c;
  c.observer = &observer(settings.observer);
  c.tristimulusObserver = settings.mode == RenderMode::Rgb ? &cie1931Observer() : c.observer;
  c.sceneColourSpace = &colourSpace(scene.colourSpace);
  if (c.tristimulusObserver->isCamera) {
    const Spectrum light = sceneEmission(scene, *c.sceneColourSpace, table);
    c.display = resolveDisplay(settings.display, *c.tristimulusObserver, &light);
  } else {
    c.display = resolveDisplay(settings.display, *c.tristimulusObserver);
  }
  c.wavelengths = wavelengths ? std::move(wavelengths)
                              : std::make_shared<const WavelengthSampler>(sceneWavelengthSampler(
                                    effectiveSampling(settings), *c.observer, scene, *c.sceneColourSpace, table));
  if (environmentFromAbove) {
    c.environmentFromAbove = std::move(*environmentFromAbove);
  } else if (scene.techniques.medium(scene.camera.position)) {
    if (std::shared_ptr<const TechniqueEnvironment> e = scene.techniques.environment(table)) {
      c.environmentFromAbove = std::make_shared<const Spectrum>(e->scalarIrradianceFromAbove());
    }
  }
  return c;
}

}  // namespace prism::render
