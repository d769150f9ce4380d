#include "gpu/window_context.h"

#include <GLFW/glfw3.h>
#include <epoxy/gl.h>

#include <mutex>
#include <string_view>

#include "gpu/error.h"

namespace prism::gpu {
namespace {

constexpr std::string_view kInstallHint =
    "install the Debian packages libgl1-mesa-dri libegl-mesa0 libglfw3 and run under an X "
    "server (DISPLAY set)";

// GLFW is process-wide: initialised for the first window and terminated after the last.
std::mutex gGlfwMutex;
int gGlfwUsers = 0;

// GLFW's last error as text on one line, or `fallback`.
std::string glfwReason(std::string_view fallback) {
  const char* description = nullptr;
  int code = glfwGetError(&description);
  std::string reason = code != GLFW_NO_ERROR && description ? description : std::string(fallback);
  for (char& c : reason)
    if (c == '\n' || c == '\r') c = ' ';
  return reason;
}

[[noreturn]] void fail(const std::string& reason) {
  throw GpuError(Diagnostic::NoOpenGl45, "no OpenGL 4.5 core context in a GLFW window (" + reason +
                                             "); " + std::string(kInstallHint));
}

void acquireGlfw() {
  std::lock_guard lock(gGlfwMutex);
  if (gGlfwUsers == 0) {
    glfwGetError(nullptr);  // forget errors from before
    if (!glfwInit()) fail(glfwReason("glfwInit failed"));
  }
  ++gGlfwUsers;
}

void releaseGlfw() {
  std::lock_guard lock(gGlfwMutex);
  if (--gGlfwUsers == 0) glfwTerminate();
}

}  // namespace

WindowContext::WindowContext(const WindowDesc& desc) {
  acquireGlfw();
  try {
    glfwDefaultWindowHints();
    glfwWindowHint(GLFW_CLIENT_API, GLFW_OPENGL_API);
    glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 4);
    glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 5);
    glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
    glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
    glfwWindowHint(GLFW_OPENGL_DEBUG_CONTEXT, desc.debugContext ? GLFW_TRUE : GLFW_FALSE);
    glfwWindowHint(GLFW_VISIBLE, desc.visible ? GLFW_TRUE : GLFW_FALSE);
    int width = desc.width > 0 ? desc.width : 1280;
    int height = desc.height > 0 ? desc.height : 720;
    std::string title = desc.title.empty() ? "Prism" : desc.title;
    mWindow = glfwCreateWindow(width, height, title.c_str(), nullptr, nullptr);
    if (!mWindow) fail(glfwReason("glfwCreateWindow failed"));
    glfwMakeContextCurrent(mWindow);
    GLint major = 0, minor = 0, profile = 0;
    glGetIntegerv(GL_MAJOR_VERSION, &major);
    glGetIntegerv(GL_MINOR_VERSION, &minor);
    glGetIntegerv(GL_CONTEXT_PROFILE_MASK, &profile);
    if (major * 10 + minor < 45 || !(profile & GL_CONTEXT_CORE_PROFILE_BIT))
      fail("got OpenGL " + std::to_string(major) + "." + std::to_string(minor) +
           ((profile & GL_CONTEXT_CORE_PROFILE_BIT) ? " core" : " compatibility"));
    glfwSwapInterval(desc.vsync ? 1 : 0);
  } catch (...) {
    if (mWindow) glfwDestroyWindow(mWindow);
    releaseGlfw();
    throw;
  }
  auto string = [](GLenum name) {
    const GLubyte* s = glGetString(name);
    return s ? std::string(reinterpret_cast<const char*>(s)) : std::string();
  };
  mRenderer = string(GL_RENDERER);
  mVersion = string(GL_VERSION);
  mDebug = std::make_unique<DebugOutput>(desc.debugNotifications);
}

WindowContext::~WindowContext() {
  glfwMakeContextCurrent(mWindow);  // the debug callback belongs to this context
  mDebug.reset();
  glfwDestroyWindow(mWindow);
  releaseGlfw();
}

bool WindowContext::shouldClose() const { return glfwWindowShouldClose(mWindow) != 0; }

void WindowContext::swapBuffers() { glfwSwapBuffers(mWindow); }

void WindowContext::pollEvents() { glfwPollEvents(); }

WindowSize WindowContext::framebufferSize() const {
  WindowSize size;
  glfwGetFramebufferSize(mWindow, &size.width, &size.height);
  return size;
}

Framebuffer WindowContext::framebuffer() const {
  WindowSize size = framebufferSize();
  return Framebuffer::window(size.width, size.height);
}

void WindowContext::makeCurrent() { glfwMakeContextCurrent(mWindow); }

}  // namespace prism::gpu
