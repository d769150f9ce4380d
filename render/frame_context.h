// What a frame's settings name, resolved: the observer, the scene's colour space, the display
// transform's inputs, the wavelength sampler and the environment's light over a medium. Built
// once whenever the settings change (Renderer's constructor and setSettings) or the scene does
// (Renderer::sceneChanged: the Lights strategy's pdf follows its lights) and handed to frame
// assembly and the display transform, so no frame looks a name up or tabulates a pdf again.
#pragma once

#include <memory>
#include <optional>

#include "render/display_transform.h"
#include "render/frame_settings.h"
#include "scene/scene.h"
#include "spectral/colour_space.h"
#include "spectral/observer.h"
#include "spectral/rgb_to_spectrum_table.h"
#include "spectral/sampling.h"

namespace prism::render {

struct FrameContext {
  const Observer* observer = nullptr;             // FrameSettings::observer
  const Observer* tristimulusObserver = nullptr;  // whose tristimulus the lighting pass writes:
                                                  // CIE 1931 in RGB mode, else `observer`
  const RgbColourSpace* sceneColourSpace = nullptr;
  DisplayInputs display;
  // Draws each frame's wavelengths (effectiveSampling(settings); Lights follows the scene's
  // emission, scene/scene_emission.h). Shared: copies of a context share one pdf.
  std::shared_ptr<const WavelengthSampler> wavelengths;
  // The distant environment's scalarIrradianceFromAbove (techniques/technique_section.h) where a
  // technique medium scatters it (PRT's environment over the water); null otherwise.
  std::shared_ptr<const Spectrum> environmentFromAbove;
};

// Error on an unknown name. The pointers are to data that lives as long as the program. `table` is
// the scene colour space's Jakob–Hanika table (the background's emission). `environmentFromAbove`,
// when given, is taken as it is: it follows the scene, not the settings (Renderer::setSettings
// keeps the one it has rather than summing a map's texels again). So is `wavelengths`, a sampler
// made for the same effective sampling, observer and scene: making one reads the fitted set from
// the cache (8 ms for an example scene), which an exposure dragged in the viewer paid every frame.
FrameContext frameContext(const FrameSettings& settings, const Scene& scene, const RgbToSpectrumTable& table,
                          std::optional<std::shared_ptr<const Spectrum>> environmentFromAbove = std::nullopt,
                          std::shared_ptr<const WavelengthSampler> wavelengths = nullptr);

}  // namespace prism::render
