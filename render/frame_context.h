// What a frame's settings name, resolved: the observer, the scene's colour space and the display
// transform's inputs. Built once whenever the settings change (Renderer's constructor and
// setSettings) and handed to frame assembly and the display transform, so no frame looks a name
// up again.
#pragma once

#include "render/display_transform.h"
#include "render/frame_settings.h"
#include "scene/scene.h"
#include "spectral/colour_space.h"
#include "spectral/observer.h"

namespace prism::render {

struct FrameContext {
  const Observer* observer = nullptr;             // FrameSettings::observer
  const Observer* tristimulusObserver = nullptr;  // whose tristimulus the lighting pass writes:
                                                  // CIE 1931 in RGB mode, else `observer`
  const RgbColourSpace* sceneColourSpace = nullptr;
  DisplayInputs display;
};

// Error on an unknown name. The pointers are to data that lives as long as the program.
FrameContext frameContext(const FrameSettings& settings, const Scene& scene);

}  // namespace prism::render
