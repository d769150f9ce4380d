#include "render/frame_context.h"

namespace prism::render {

FrameContext frameContext(const FrameSettings& settings, const Scene& scene) {
  FrameContext c;
  c.observer = &observer(settings.observer);
  c.tristimulusObserver = settings.mode == RenderMode::Rgb ? &cie1931Observer() : c.observer;
  c.sceneColourSpace = &colourSpace(scene.colourSpace);
  c.display = resolveDisplay(settings.display, *c.tristimulusObserver);
  return c;
}

}  // namespace prism::render
