#include "viewer/compositor.h"

#include <epoxy/gl.h>
#include <imgui.h>

#include <span>
#include <vector>

#include "gpu/framebuffer.h"
#include "imaging/exr_file.h"
#include "imaging/heatmap.h"
#include "render/display_transform.h"
#include "core/error.h"
#include "spectral/observer.h"

namespace prism::viewer {
namespace {

// The luminance the view's exposure maps to display white.
double whiteLuminance(const render::FrameSettings& s, const Camera& camera) {
  return render::displayWhiteLuminance(s.display.ev100.value_or(camera.ev100));
}

}  // namespace

void Compositor::renderView(std::unique_ptr<render::Renderer>& renderer, Pending& pending,
                            render::FrameSettings settings, const Camera& camera, int width, int height) {
  settings.width = width;
  settings.height = height;
  if (!renderer) {
    renderer = std::make_unique<render::Renderer>(mScene, mTable, settings);
    pending = {false, true, false};
  } else if (pending.settings || renderer->settings().width != width || renderer->settings().height != height) {
    renderer->setSettings(settings);
  }
  pending.settings = false;
  if (pending.camera) renderer->setCamera(camera);
  if (pending.scene) renderer->sceneChanged();
  pending.camera = pending.scene = false;
  renderer->renderFrame();
}

std::string Compositor::render(ViewSettings& view, const Changes& changes, const Camera& camera, int width,
                               int height) {
  if (changes.settings) mLeftPending.settings = mRightPending.settings = true;
  if (changes.camera) mLeftPending.camera = mRightPending.camera = true;
  if (changes.scene) mLeftPending.scene = mRightPending.scene = true;
  std::string error;
  try {
    renderView(mLeft, mLeftPending, view.left, camera, width, height);
  } catch (const std::exception& e) {
    error = e.what();  // a bad setting or shader: keep the last good settings
    if (mLeft) view.left = mLeft->settings();
  }
  // The right view's renderer stays once made (hidden when the split is off): making one
  // compiles every pass again, which the driver does not give back to the system at once.
  if (view.split) {
    try {
      renderView(mRight, mRightPending, view.right, camera, width, height);
    } catch (const std::exception& e) {
      error = e.what();
      if (mRight) view.right = mRight->settings();
      else view.split = false;  // it cannot be made: no split rather than a retry every frame
    }
  }
  try {
    if (view.split && view.heatMap && mLeft && mRight && ++mFramesSinceHeatMap >= 15) updateHeatMap(camera);
  } catch (const std::exception& e) {
    error = mHeatError = e.what();
    view.heatMap = false;
  }
  if (!(view.split && view.heatMap)) mHeatTexture = gpu::Texture2D();  // its GL object goes with it
  return error;
}

void Compositor::compose(const ViewSettings& view, int width, int height) const {
  gpu::Framebuffer::window(width, height).bind();
  glClearColor(0.0f, 0.0f, 0.0f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT);
  if (!mLeft) return;
  int half = view.split && mRight ? width / 2 : width;
  glBlitNamedFramebuffer(mLeft->displayFramebuffer().id(), 0, 0, 0, half, height, 0, 0, half, height,
                         GL_COLOR_BUFFER_BIT, GL_NEAREST);
  if (view.split && mRight) {
    glBlitNamedFramebuffer(mRight->displayFramebuffer().id(), 0, half, 0, width, height, half, 0, width, height,
                           GL_COLOR_BUFFER_BIT, GL_NEAREST);
    ImGui::GetBackgroundDrawList()->AddLine(ImVec2(static_cast<float>(half), 0.0f),
                                            ImVec2(static_cast<float>(half), static_cast<float>(height)),
                                            IM_COL32(255, 255, 255, 160), 1.0f);
  }
}

void Compositor::updateHeatMap(const Camera& camera) {
  mFramesSinceHeatMap = 0;
  const render::FrameSettings& s = mLeft->settings();
  const render::FrameSettings& t = mRight->settings();
  // CIE 1931 XYZ, or a camera's RGB through its matrix, on each side (as `prism compare` takes
  // them): one camera against the eye shows the camera's own colour error.
  const render::FrameContext& left = mLeft->context();
  const render::FrameContext& right = mRight->context();
  for (const render::FrameContext* c : {&left, &right})
    if (!c->tristimulusObserver->isCamera &&
        imaging::tristimulusMeaning(*c->tristimulusObserver) != imaging::ColourMeaning::Xyz)
      throw Error("the heat map compares CIE 1931 XYZ, or a camera's RGB through its matrix: choose cie1931 or a "
                  "camera on each side (CIE 1964's X10Y10Z10 is neither)");
  imaging::FloatImage a(s.width, s.height, 3), b(t.width, t.height, 3);
  a.pixels = mLeft->readMeanTristimulus();
  b.pixels = mRight->readMeanTristimulus();
  const auto input = [&](const imaging::FloatImage& image, const render::FrameContext& c, double white) {
    return c.tristimulusObserver->isCamera ? imaging::cameraInput(image, c.display.tristimulusToXyz, white)
                                           : imaging::linearInput(image, imaging::ColourMeaning::Xyz, white);
  };
  imaging::DifferenceOptions options;
  options.keepMap = true;
  imaging::ImageDifference d = imaging::compareImages(input(a, left, whiteLuminance(s, camera)),
                                                      input(b, right, whiteLuminance(t, camera)), options);
  mHeatStats = d.stats;
  mHeatError.clear();
  imaging::PngImage heat = imaging::heatMap(d.deltaEMap, {.maxDeltaE = 5.0, .legend = true});
  gpu::Texture2DDesc desc;
  desc.width = heat.width();
  desc.height = heat.height();
  desc.internalFormat = GL_RGBA8;
  desc.data = {GL_RGBA, GL_UNSIGNED_BYTE, std::as_bytes(std::span(heat.rgba()))};
  desc.label = "viewer heat map";
  mHeatTexture = gpu::Texture2D(desc);
}

void Compositor::writeLeftExr(const std::filesystem::path& path, const Camera& camera) const {
  if (!mLeft) throw Error("nothing rendered yet");
  const render::FrameSettings& s = mLeft->settings();
  imaging::FloatImage image(s.width, s.height, 3);
  image.pixels = mLeft->readMeanTristimulus();
  const render::FrameContext& frame = mLeft->context();
  imaging::writeExr(path, image, imaging::tristimulusExr(*frame.tristimulusObserver, whiteLuminance(s, camera),
                                                         frame.display.tristimulusToXyz));
}

void Compositor::reloadShaders() {
  if (mLeft) mLeft->reloadShaders();
  if (mRight) mRight->reloadShaders();
}

}  // namespace prism::viewer
