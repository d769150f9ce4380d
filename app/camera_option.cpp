#include "app/camera_option.h"

#include <fmt/format.h>

#include <cstdio>

#include "core/error.h"

namespace prism::app {

const Observer& cameraOption(const std::string& name) {
  const Observer* camera = nullptr;
  try {
    camera = &observer(name);
  } catch (const Error&) {
  }
  if (!camera || !camera->isCamera)
    throw Error(fmt::format("--camera: \"{}\" is not a camera (see `prism colour list cameras`)", excerpt(name)));
  return *camera;
}

void warnIfIllPosed(double chartConditioning, std::string_view light, std::string_view camera) {
  if (chartConditioning < kIllPosedCameraFit)
    fmt::print(stderr, "prism: warning: under {} the ColorChecker's colours through {} barely span three dimensions "
                       "(smallest / largest singular value {:.2g}): the matrix is one of many that fit the chart, and "
                       "maps light of another spectrum arbitrarily\n", light, camera, chartConditioning);
}

}  // namespace prism::app
