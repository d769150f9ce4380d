#include "render/display_transform.h"

#include "core/error.h"
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

// Fitted on the ColorChecker under the light and scaled to keep its luminance — the fit
// normalises camera RGB and XYZ each by its own white's green and Y, while the renderer scales
// camera RGB to match XYZ under D65 (absoluteTristimulusScale), so the ratio of the two
// normalisations (1 under D65). A light the eye or the camera's green does not see (a 790 nm LED)
// fits nothing: D65's matrix then, which shows the next to nothing the camera sees of it as such.
CameraMatrixFit sceneCameraFit(const Observer& camera, const Spectrum* lightOrNull) {
  PRISM_CHECK(camera.isCamera);
  const Spectrum& light = lightOrNull ? *lightOrNull : illuminant("D65");
  const Observer& cie = cie1931Observer();
  const Spectrum& d65 = illuminant("D65");
  auto greenOverY = [&](const Spectrum& s) { return camera.integrate(s).y() / cie.integrate(s).y(); };
  auto fitted = [&](const Spectrum& s) {
    CameraMatrixFit fit = fitCameraToXyz(camera, s, cie);
    fit.cameraToXyz *= greenOverY(d65) / greenOverY(s);
    return fit;
  };
  if (cameraSees(camera, light))
    if (CameraMatrixFit fit = fitted(light); fit.cameraToXyz.allFinite()) return fit;
  return fitted(d65);
}

}  // namespace

Eigen::Matrix3d cameraToXyz(const Observer& camera, const Spectrum* light) {
  return sceneCameraFit(camera, light).cameraToXyz;
}

DisplayInputs resolveDisplay(const DisplaySettings& settings, const Observer& tristimulusObserver,
                             const Spectrum* cameraLight) {
  DisplayInputs inputs;
  inputs.colourSpace = &colourSpace(settings.colourSpace);
  if (tristimulusObserver.isCamera) {
    const CameraMatrixFit fit = sceneCameraFit(tristimulusObserver, cameraLight);
    inputs.tristimulusToXyz = fit.cameraToXyz;
    inputs.cameraChartConditioning = fit.chartConditioning;
  }
  if (settings.whiteBalance != "none") {
    // The white a surface lit by the illuminant shows: its tristimulus under this observer, or for
    // a camera its raw white through the matrix fitted under that illuminant — the image's own
    // matrix when it is the scene's light, so that the light's grey shows exactly neutral. (The
    // image's matrix for another white: fitted under a narrow LED it gave D65 a negative Y.)
    const Spectrum wb = lampSpectrum(settings.whiteBalance);
    Eigen::Vector3d white = tristimulusObserver.integrate(wb);
    if (tristimulusObserver.isCamera) white = cameraToXyz(tristimulusObserver, &wb) * white;
    inputs.whiteBalanceXyz = white / white.y();
  }
  return inputs;
}

DisplayTransform displayTransform(const DisplaySettings& settings, const DisplayInputs& inputs, float sceneEv100) {
  const RgbColourSpace& display = *inputs.colourSpace;
  Eigen::Matrix3d m = inputs.tristimulusToXyz;
  if (inputs.whiteBalanceXyz) {
    m = chromaticAdaptation(settings.adaptation, *inputs.whiteBalanceXyz, display.whiteXyz()) * m;
  }
  float exposure = shared::exposureScale(settings.ev100.value_or(sceneEv100));
  DisplayTransform t;
  t.toDisplay = toGlm(display.xyzToRgb * m) * exposure;
  t.displayToXyz = toGlm(display.rgbToXyz);
  t.xyzToDisplay = toGlm(display.xyzToRgb);
  t.transfer = display.transfer == Transfer::Bt2020 ? 1 : 0;
  t.toXyz = toGlm(inputs.tristimulusToXyz);
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
