// An OpenGL 4.5 core context in a window, through GLFW (X11 on Debian): the viewer's context,
// where HeadlessContext is everyone else's. Its default framebuffer is the window's back buffer
// (framebuffer() wraps it for clears and blits); window() is the GLFWwindow* for input
// callbacks. The context is current on the constructing thread, which must be the main thread
// (GLFW's rule). GLFW is initialised by the first live WindowContext and terminated by the last.
//
// When GLFW cannot initialise (no X server, DISPLAY unset or wrong), the window or context cannot
// be created, or the context is below 4.5 core, the constructor throws GpuError(NoOpenGl45)
// whose message is one line: GLFW's reason and the Debian packages to install. This lives in
// its own target, prism_gpu_window, so that prism::gpu itself needs neither GLFW nor X11.
#pragma once

#include <memory>
#include <string>

#include "gpu/debug_output.h"
#include "gpu/framebuffer.h"

struct GLFWwindow;

namespace prism::gpu {

struct WindowDesc {
  int width = 0, height = 0;        // in screen coordinates; 0 means 1280×720
  std::string title;                // empty means "Prism"
  bool visible = true;              // false: an off-screen window (tests, captures)
  bool vsync = true;                // swap interval 1, else 0
  bool debugContext = true;         // GLFW_OPENGL_DEBUG_CONTEXT: the driver checks more
  bool debugNotifications = false;  // also route GL_DEBUG_SEVERITY_NOTIFICATION messages
};

struct WindowSize {
  int width = 0, height = 0;
};

class WindowContext {
 public:
  explicit WindowContext(const WindowDesc& desc = {});
  ~WindowContext();
  WindowContext(const WindowContext&) = delete;
  WindowContext& operator=(const WindowContext&) = delete;

  bool shouldClose() const;
  void swapBuffers();
  void pollEvents();  // glfwPollEvents: runs input callbacks, never waits
  // In pixels, which differ from screen coordinates on high-DPI displays; 0×0 when minimised.
  WindowSize framebufferSize() const;
  // The default framebuffer at its current size.
  Framebuffer framebuffer() const;
  GLFWwindow* window() const { return mWindow; }

  void makeCurrent();
  const std::string& renderer() const { return mRenderer; }  // GL_RENDERER
  const std::string& version() const { return mVersion; }    // GL_VERSION
  DebugOutput& debugOutput() { return *mDebug; }

 private:
  GLFWwindow* mWindow = nullptr;
  std::unique_ptr<DebugOutput> mDebug;
  std::string mRenderer, mVersion;
};

}  // namespace prism::gpu
