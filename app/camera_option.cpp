#include "app/camera_option.h"

#include <fmt/format.h>

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

}  // namespace prism::app
