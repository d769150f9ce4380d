// The viewer's window and frame loop: the mouse and keys move the camera, the compositor renders
// and shows the views, the interface's panels are drawn over them, the buffers swap. A person
// runs it until the window closes (interactive); the script runner (script.h) runs the same
// frames and edits the same state through the accessors.
#pragma once

#include <array>
#include <chrono>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "gpu/window_context.h"
#include "render/frame_settings.h"
#include "scene/scene.h"
#include "spectral/rgb_to_spectrum_table.h"
#include "viewer/camera_controller.h"
#include "viewer/changes.h"
#include "viewer/compositor.h"
#include "viewer/panel.h"
#include "viewer/viewer_settings.h"

namespace prism::viewer {

class Viewer {
 public:
  Viewer(gpu::WindowContext& window, Scene& scene, const RgbToSpectrumTable& table,
         const render::FrameSettings& initial);
  Viewer(const Viewer&) = delete;
  Viewer& operator=(const Viewer&) = delete;

  // Frames until the window closes; errors are shown in the window, not thrown. Returns 0.
  int interactive();

  // One frame: input, both views, the window, the interface, the swap.
  void frame();
  // Resizes the window and waits (briefly) for its framebuffer to follow.
  void resize(int width, int height);
  // .png: the window as shown, interface included; .exr: the left view's tristimulus. renderNow:
  // take it in a frame of its own (the script); otherwise in this frame (from the interface).
  void screenshot(const std::filesystem::path& path, bool renderNow);
  void loadSettings(const std::filesystem::path& path);  // viewer_settings.h's files
  void saveSettings(const std::filesystem::path& path) const;
  void reloadShaders();

  gpu::WindowContext& window() { return mWindow; }
  Scene& scene() { return mScene; }
  ViewSettings& view() { return mView; }
  CameraController& camera() { return mCamera; }
  Changes& changes() { return mChanges; }  // what the next frame's renderers take
  const Compositor& compositor() const { return mCompositor; }
  const std::string& renderError() const { return mRenderError; }  // from the last frame's rendering

 private:
  // Dear ImGui over the window, from construction to destruction.
  class ImGuiSession {
   public:
    explicit ImGuiSession(gpu::WindowContext& window);
    ~ImGuiSession();
    ImGuiSession(const ImGuiSession&) = delete;
    ImGuiSession& operator=(const ImGuiSession&) = delete;
  };

  // Error unless `path` is none of the files the scene reads (its file, models, textures, maps):
  // screenshots and settings files are never written over them.
  void requireOutputClear(const std::filesystem::path& path) const;
  void handleInput(float seconds);
  void interface();
  void writeWindowPng(const std::filesystem::path& path, int width, int height) const;

  gpu::WindowContext& mWindow;
  Scene& mScene;
  const RgbToSpectrumTable& mTable;
  CameraController mCamera;
  ViewSettings mView;
  Changes mChanges;
  std::string mRenderError;  // shown in red
  std::string mActionError;  // from the last action in the interface, shown until dismissed
  ImGuiSession mImGui;
  Compositor mCompositor;  // goes before ImGui, as the window's GL objects always did
  std::vector<std::unique_ptr<Panel>> mPanels;
  float mFlySpeed = 1.0f;  // m/s
  double mCursorX = 0.0, mCursorY = 0.0;
  std::chrono::steady_clock::time_point mLastFrame = std::chrono::steady_clock::now();
  std::array<float, 120> mFrameMs{};
  std::size_t mFrameCursor = 0;
  std::filesystem::path mPendingScreenshot;  // written after the interface is drawn, before the swap
};

}  // namespace prism::viewer
