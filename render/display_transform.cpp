#include "render/display_transform.h"

#include "render/shared_shading.h"
#include "spectral/camera_matrix.h"
#include "spectral/colour_space.h"
#include "spectral/illuminant.h"
#include "spectral/observer.h"

namespace prism::render {
namespace {

glm::mat3 toGlm(const Eigen::Matrix3d& m) {
  glm::mat3 g;
  for (int r = 0; r < 3; ++r) {
    for (int c = 0; c < 3; ++c) g[c][r] = static_cast<float>(m(r, c));  // GLM is column-major
  }
  return g;
}

}  // namespace

DisplayInputs resolveDisplay(const DisplaySettings& settings, const Observer& tristimulusObserver,
                             const Spectrum* cameraLight) {
  DisplayInputs inputs;
  inputs.colourSpace = &colourSpace(settings.colourSpace);
  if (tristimulusObserver.isCamera) {
    const Observer& cie = cie1931Observer();
    const Spectrum& d65 = illuminant("D65");
    const bool lit = cameraLight && cie.integrate(*cameraLight).y() > 0.0;
    const Spectrum& light = lit ? *cameraLight : d65;
    // The fit maps camera RGB to XYZ each normalised by its own white's green and Y under `light`;
    // the renderer scales camera RGB to match XYZ under D65 (absoluteTristimulusScale). The ratio of
    // the two normalisations keeps a light's luminance (1 under D65).
    auto greenOverY = [&](const Spectrum& s) { return tristimulusObserver.integrate(s).y() / cie.integrate(s).y(); };
    inputs.tristimulusToXyz = fitCameraToXyz(tristimulusObserver, light, cie).cameraToXyz * (greenOverY(d65) / greenOverY(light));
  }
  if (settings.whiteBalance != "none") {
    // The white the image holds: the illuminant as this observer (or camera, then its matrix) sees
    // it — a camera's own white, CIE 1964's X₁₀Y₁₀Z₁₀ — so that a surface lit by it shows neutral.
    Eigen::Vector3d white = inputs.tristimulusToXyz * tristimulusObserver.integrate(illuminant(settings.whiteBalance));
    inputs.whiteBalanceXyz = white / white.y();
  }
  return inputs;
}

DisplayTransform displayTransform(const DisplaySettings& settings, const DisplayInputs& inputs, float sceneEv100) {
  const RgbColourSpace& display = *inputs.colourSpace;
  const Eigen::Matrix3d& cameraToXyz = inputs.tristimulusToXyz;
  Eigen::Matrix3d m = cameraToXyz;
  if (inputs.whiteBalanceXyz) {
    m = chromaticAdaptation(settings.adaptation, *inputs.whiteBalanceXyz, display.whiteXyz()) * m;
  }
  float exposure = shared::exposureScale(settings.ev100.value_or(sceneEv100));
  DisplayTransform t;
  t.toDisplay = toGlm(display.xyzToRgb * m) * exposure;
  t.displayToXyz = toGlm(display.rgbToXyz);
  t.xyzToDisplay = toGlm(display.xyzToRgb);
  t.transfer = display.transfer == Transfer::Bt2020 ? 1 : 0;
  t.toXyz = toGlm(cameraToXyz);
  return t;
}

double displayWhiteLuminance(float ev100) { return 1.0 / shared::exposureScale(ev100); }

glm::vec3 encodeForDisplay(const DisplayTransform& transform, ToneMap toneMap,
                           const glm::vec3& tristimulus) {
  glm::vec3 rgb = shared::encodeForDisplay(transform.toDisplay, transform.displayToXyz, transform.xyzToDisplay,
                                           static_cast<int>(toneMap), transform.transfer, tristimulus);
  return glm::clamp(rgb, glm::vec3(0.0f), glm::vec3(1.0f));
}

}  // namespace prism::render
