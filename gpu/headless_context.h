// An OpenGL 4.5 core context with no window and no X display, through EGL (PLATFORM.md):
//   1. EGL_MESA_platform_surfaceless (Mesa: a GPU's render node, else llvmpipe), then
//   2. EGL_EXT_platform_device, each enumerated device in turn (what NVIDIA's driver offers);
// on each display: eglBindAPI(EGL_OPENGL_API), a configless context (EGL_KHR_no_config_context)
// of version 4.5, core profile, made current with no surface (EGL_KHR_surfaceless_context).
// Render into framebuffers; there is no default one.
//
// The context is current on the constructing thread for the object's whole life. When no
// candidate yields a 4.5 core context, the constructor throws GpuError(ContextUnavailable)
// whose message is one line: why, and which Debian packages to install.
#pragma once

#include <memory>
#include <string>

#include "gpu/debug_output.h"

namespace prism::gpu {

struct ContextDesc {
  bool debugContext = true;         // EGL_CONTEXT_OPENGL_DEBUG: the driver checks more
  bool debugNotifications = false;  // also route GL_DEBUG_SEVERITY_NOTIFICATION messages
};

class HeadlessContext {
 public:
  explicit HeadlessContext(const ContextDesc& desc = {});
  ~HeadlessContext();
  HeadlessContext(const HeadlessContext&) = delete;
  HeadlessContext& operator=(const HeadlessContext&) = delete;

  const std::string& renderer() const {
    return mRenderer;
  }  // GL_RENDERER, e.g. "llvmpipe (LLVM 15.0.6, 256 bits)"
  const std::string& vendor() const { return mVendor; }            // GL_VENDOR
  const std::string& version() const { return mVersion; }          // GL_VERSION
  const std::string& glslVersion() const { return mGlslVersion; }  // GL_SHADING_LANGUAGE_VERSION
  const std::string& platform() const { return mPlatform; }        // "surfaceless" or "device N"

  // Makes this context current on the calling thread again (after another one was).
  void makeCurrent();

  // The KHR_debug output of this context; its default sink prints to stderr.
  DebugOutput& debugOutput() { return *mDebug; }

 private:
  struct Egl;
  std::unique_ptr<Egl> mEgl;
  std::unique_ptr<DebugOutput> mDebug;
  std::string mRenderer, mVendor, mVersion, mGlslVersion, mPlatform;
};

}  // namespace prism::gpu
