#include "viewer/viewer_loop.h"

#include <epoxy/gl.h>
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <imgui.h>
#include <backends/imgui_impl_glfw.h>
#include <backends/imgui_impl_opengl3.h>

#include <algorithm>
#include <cstdint>

#include <fmt/format.h>

#include "imaging/png_file.h"
#include "core/error.h"
#include "core/file_extension.h"
#include "viewer/panels.h"

namespace prism::viewer {

Viewer::ImGuiSession::ImGuiSession(gpu::WindowContext& window) {
  IMGUI_CHECKVERSION();
  ImGui::CreateContext();
  ImGui::GetIO().IniFilename = nullptr;  // no imgui.ini written beside the user's files
  ImGui::StyleColorsDark();
  ImGui_ImplGlfw_InitForOpenGL(window.window(), true);
  ImGui_ImplOpenGL3_Init("#version 450");
}

Viewer::ImGuiSession::~ImGuiSession() {
  ImGui_ImplOpenGL3_Shutdown();
  ImGui_ImplGlfw_Shutdown();
  ImGui::DestroyContext();
}

Viewer::Viewer(gpu::WindowContext& window, Scene& scene, const RgbToSpectrumTable& table,
               const render::FrameSettings& initial)
    : mWindow(window), mScene(scene), mTable(table), mCamera(scene.camera), mView(initialView(initial)), mImGui(window),
      mCompositor(scene, table) {
  Bounds b = sceneBounds(scene);
  mFlySpeed = std::max(0.5f, 0.25f * glm::length(b.max - b.min));
  mPanels.push_back(makeCameraPanel());
  mPanels.push_back(makeSpectralPanel());
  mPanels.push_back(makeSplitPanel());
  mPanels.push_back(makeLightsPanel());
  mPanels.push_back(makeMaterialsPanel());
  for (std::unique_ptr<Panel>& panel : makeTechniquePanels()) mPanels.push_back(std::move(panel));
  mPanels.push_back(makeDisplayPanel());
  mPanels.push_back(makeFilesPanel(*this));
}

int Viewer::interactive() {
  while (!mWindow.shouldClose()) frame();
  return 0;
}

void Viewer::frame() {
  auto now = std::chrono::steady_clock::now();
  float seconds = std::chrono::duration<float>(now - mLastFrame).count();
  mLastFrame = now;
  mFrameMs[mFrameCursor++ % mFrameMs.size()] = seconds * 1000.0f;

  mWindow.pollEvents();
  gpu::WindowSize size = mWindow.framebufferSize();
  ImGui_ImplOpenGL3_NewFrame();
  ImGui_ImplGlfw_NewFrame();
  ImGui::NewFrame();
  if (size.width > 0 && size.height > 0) {  // minimised: nothing to draw into
    handleInput(std::min(seconds, 0.1f));
    mRenderError = mCompositor.render(mView, mChanges, mCamera.camera(), size.width, size.height);
    mChanges = {};
    mCompositor.compose(mView, size.width, size.height);
  }
  interface();
  ImGui::Render();
  if (size.width > 0 && size.height > 0) {
    ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
    if (!mPendingScreenshot.empty()) {
      writeWindowPng(mPendingScreenshot, size.width, size.height);
      mPendingScreenshot.clear();
    }
  }
  mWindow.swapBuffers();
}

void Viewer::handleInput(float seconds) {
  ImGuiIO& io = ImGui::GetIO();
  GLFWwindow* w = mWindow.window();
  double x = 0.0, y = 0.0;
  glfwGetCursorPos(w, &x, &y);
  float dx = static_cast<float>(x - mCursorX), dy = static_cast<float>(y - mCursorY);
  mCursorX = x;
  mCursorY = y;
  if (!io.WantCaptureMouse) {
    if (glfwGetMouseButton(w, GLFW_MOUSE_BUTTON_LEFT) == GLFW_PRESS && (dx != 0.0f || dy != 0.0f)) {
      mCamera.orbit(-dx * 0.005f, dy * 0.005f);
      mChanges.camera = true;
    }
    if (glfwGetMouseButton(w, GLFW_MOUSE_BUTTON_RIGHT) == GLFW_PRESS && (dx != 0.0f || dy != 0.0f)) {
      mCamera.look(-dx * 0.003f, -dy * 0.003f);
      mChanges.camera = true;
    }
    if (glfwGetMouseButton(w, GLFW_MOUSE_BUTTON_MIDDLE) == GLFW_PRESS && (dx != 0.0f || dy != 0.0f)) {
      mCamera.pan(-dx * 0.002f, dy * 0.002f);
      mChanges.camera = true;
    }
    if (io.MouseWheel != 0.0f) {
      mCamera.dolly(0.1f * io.MouseWheel);
      mChanges.camera = true;
    }
  }
  if (!io.WantCaptureKeyboard) {
    glm::vec3 move(0.0f);
    auto key = [&](int k) { return glfwGetKey(w, k) == GLFW_PRESS ? 1.0f : 0.0f; };
    move.x = key(GLFW_KEY_D) - key(GLFW_KEY_A);
    move.y = key(GLFW_KEY_E) - key(GLFW_KEY_Q);
    move.z = key(GLFW_KEY_W) - key(GLFW_KEY_S);
    if (move != glm::vec3(0.0f)) {
      mCamera.fly(move * mFlySpeed * seconds);
      mChanges.camera = true;
    }
    if (key(GLFW_KEY_R) > 0.0f) {
      mCamera.reset();
      mChanges.camera = true;
    }
  }
}

// The frame time, the errors, then each panel that applies under its header.
void Viewer::interface() {
  ImGui::SetNextWindowPos(ImVec2(10, 10), ImGuiCond_FirstUseEver);
  ImGui::SetNextWindowSize(ImVec2(430, std::max(200.0f, ImGui::GetIO().DisplaySize.y - 20.0f)), ImGuiCond_FirstUseEver);
  ImGui::Begin("Prism");
  float mean = 0.0f;
  for (float ms : mFrameMs) mean += ms;
  mean /= static_cast<float>(mFrameMs.size());
  ImGui::Text("%.1f ms  %.0f FPS   %s", mean, mean > 0.0f ? 1000.0f / mean : 0.0f, mWindow.renderer().c_str());
  ImGui::PlotLines("##frame", mFrameMs.data(), static_cast<int>(mFrameMs.size()),
                   static_cast<int>(mFrameCursor % mFrameMs.size()), "frame ms", 0.0f, 2.0f * mean + 1.0f,
                   ImVec2(0, 40));
  for (const std::string* error : {&mRenderError, &mActionError}) {
    if (!error->empty()) ImGui::TextColored(ImVec4(1.0f, 0.4f, 0.4f, 1.0f), "%s", error->c_str());
  }
  if (!mActionError.empty() && ImGui::SmallButton("dismiss")) mActionError.clear();
  PanelContext context{mScene, mTable, mView, mCamera, mCompositor, mChanges, mActionError};
  for (const std::unique_ptr<Panel>& panel : mPanels) {
    ImGuiTreeNodeFlags flags = panel->openAtStart() ? ImGuiTreeNodeFlags_DefaultOpen : ImGuiTreeNodeFlags_None;
    if (panel->applies(mScene) && ImGui::CollapsingHeader(panel->title(), flags)) panel->draw(context);
  }
  ImGui::End();
}

void Viewer::writeWindowPng(const std::filesystem::path& path, int width, int height) const {
  std::vector<std::uint8_t> rgba(static_cast<std::size_t>(width) * static_cast<std::size_t>(height) * 4);
  glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
  glReadBuffer(GL_BACK);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadPixels(0, 0, width, height, GL_RGBA, GL_UNSIGNED_BYTE, rgba.data());
  imaging::PngImage image(width, height, {});
  image.setColourSpace(mView.left.display.colourSpace);  // the (left) view's display space, as the window shows it
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) {
      const std::uint8_t* p = &rgba[(static_cast<std::size_t>(height - 1 - y) * static_cast<std::size_t>(width) +
                                     static_cast<std::size_t>(x)) * 4];
      image.setPixel(x, y, {p[0], p[1], p[2]});
    }
  }
  image.write(path);
}

void Viewer::screenshot(const std::filesystem::path& path, bool renderNow) {
  requireOutputClear(path);
  if (lowercaseExtension(path) == ".exr") return mCompositor.writeLeftExr(path, mCamera.camera());
  if (lowercaseExtension(path) != ".png") throw Error(fmt::format("{}: a screenshot is a .png or an .exr", path.string()));
  requireOneDisplaySpace(mView, path);
  mPendingScreenshot = path;  // written after the interface is drawn, before the swap
  if (renderNow) {
    frame();
    if (!mPendingScreenshot.empty()) throw Error("the window is minimised: nothing to take");
  }
}

void Viewer::resize(int width, int height) {
  glfwSetWindowSize(mWindow.window(), width, height);
  // The window system answers asynchronously: wait (briefly) until the framebuffer follows.
  for (int i = 0; i < 200; ++i) {
    mWindow.pollEvents();
    gpu::WindowSize s = mWindow.framebufferSize();
    if (s.width == width && s.height == height) break;
    glfwWaitEventsTimeout(0.01);
  }
}

void Viewer::loadSettings(const std::filesystem::path& path) {
  Camera camera = mCamera.camera();
  loadViewSettings(path, mView, camera);
  mCamera = CameraController(camera);
  mChanges.settings = mChanges.camera = true;
}

void Viewer::saveSettings(const std::filesystem::path& path) const {
  requireOutputClear(path);
  saveViewSettings(path, mView, mCamera.camera());
}

void Viewer::requireOutputClear(const std::filesystem::path& path) const { requireNotSceneInput(path, mScene); }

void Viewer::reloadShaders() { mCompositor.reloadShaders(); }

}  // namespace prism::viewer
