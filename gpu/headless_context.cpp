#include "gpu/headless_context.h"

#include <dlfcn.h>
#include <epoxy/egl.h>
#include <epoxy/gl.h>

#include <mutex>
#include <set>
#include <string_view>
#include <vector>

#include "gpu/error.h"

namespace prism::gpu {
namespace {

constexpr std::string_view kInstallHint =
    "install the Debian packages libegl-mesa0 libgl1-mesa-dri libegl1 libgl1 "
    "(Mesa's llvmpipe needs no GPU)";

std::string eglErrorName(EGLint error) {
  switch (error) {
    case EGL_SUCCESS: return "EGL_SUCCESS";
    case EGL_NOT_INITIALIZED: return "EGL_NOT_INITIALIZED";
    case EGL_BAD_ACCESS: return "EGL_BAD_ACCESS";
    case EGL_BAD_ALLOC: return "EGL_BAD_ALLOC";
    case EGL_BAD_ATTRIBUTE: return "EGL_BAD_ATTRIBUTE";
    case EGL_BAD_CONTEXT: return "EGL_BAD_CONTEXT";
    case EGL_BAD_CONFIG: return "EGL_BAD_CONFIG";
    case EGL_BAD_CURRENT_SURFACE: return "EGL_BAD_CURRENT_SURFACE";
    case EGL_BAD_DISPLAY: return "EGL_BAD_DISPLAY";
    case EGL_BAD_SURFACE: return "EGL_BAD_SURFACE";
    case EGL_BAD_MATCH: return "EGL_BAD_MATCH";
    case EGL_BAD_PARAMETER: return "EGL_BAD_PARAMETER";
    case EGL_BAD_NATIVE_PIXMAP: return "EGL_BAD_NATIVE_PIXMAP";
    case EGL_BAD_NATIVE_WINDOW: return "EGL_BAD_NATIVE_WINDOW";
    case EGL_CONTEXT_LOST: return "EGL_CONTEXT_LOST";
    default: return "EGL error " + std::to_string(error);
  }
}

std::string failed(const char* call) {
  return std::string(call) + " failed (" + eglErrorName(eglGetError()) + ")";
}

// A display that has held a context stays initialised until the process exits, never
// eglTerminate'd: eglGetPlatformDisplayEXT returns one handle per device for the whole process,
// so terminating it would pull it from under any other context on it (EGL 1.5 §3.2: eglInitialize
// is not reference counted); re-initialising reloads the driver (tens of ms for llvmpipe); and
// Mesa 22 leaks a driver allocation each time its DRI driver is unloaded, which LeakSanitizer
// cannot even attribute (the frames lie in the unloaded module). A display that never yielded
// a context is terminated again.
std::mutex gDisplayMutex;
std::set<EGLDisplay> gDisplaysInUse;

void keepDisplay(EGLDisplay display) {
  std::lock_guard lock(gDisplayMutex);
  gDisplaysInUse.insert(display);
}

void releaseUnusedDisplay(EGLDisplay display) {
  std::lock_guard lock(gDisplayMutex);
  if (!gDisplaysInUse.contains(display)) eglTerminate(display);
}

// epoxy aborts the process when it cannot dlopen the EGL or GL library; check first so that a
// machine without them gets the one-line error instead. The handles stay open: epoxy uses them.
bool librariesPresent(std::string& reason) {
  if (!dlopen("libEGL.so.1", RTLD_LAZY | RTLD_GLOBAL)) {
    reason = "libEGL.so.1 not found";
    return false;
  }
  if (!dlopen("libOpenGL.so.0", RTLD_LAZY | RTLD_GLOBAL) &&
      !dlopen("libGL.so.1", RTLD_LAZY | RTLD_GLOBAL)) {
    reason = "neither libOpenGL.so.0 nor libGL.so.1 found";
    return false;
  }
  return true;
}

}  // namespace

struct HeadlessContext::Egl {
  EGLDisplay display = EGL_NO_DISPLAY;
  EGLContext context = EGL_NO_CONTEXT;

  // Creates and makes current a 4.5 core context on `display`, or says why not.
  bool tryDisplay(EGLDisplay candidate, const ContextDesc& desc, std::string& reason) {
    if (candidate == EGL_NO_DISPLAY) {
      reason = failed("eglGetPlatformDisplayEXT");
      return false;
    }
    EGLint major = 0, minor = 0;
    if (!eglInitialize(candidate, &major, &minor)) {  // a no-op on an initialised display
      reason = failed("eglInitialize");
      return false;
    }
    auto fail = [&](std::string why) {
      reason = std::move(why);
      releaseUnusedDisplay(candidate);
      return false;
    };
    if (!epoxy_has_egl_extension(candidate, "EGL_KHR_no_config_context") &&
        !epoxy_has_egl_extension(candidate, "EGL_MESA_configless_context"))
      return fail("no EGL_KHR_no_config_context");
    if (!epoxy_has_egl_extension(candidate, "EGL_KHR_surfaceless_context"))
      return fail("no EGL_KHR_surfaceless_context");
    if (!eglBindAPI(EGL_OPENGL_API)) return fail(failed("eglBindAPI(EGL_OPENGL_API)"));
    std::vector<EGLint> attributes{
        EGL_CONTEXT_MAJOR_VERSION,       4,
        EGL_CONTEXT_MINOR_VERSION,       5,
        EGL_CONTEXT_OPENGL_PROFILE_MASK, EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT};
    if (desc.debugContext)
      attributes.insert(attributes.end(), {EGL_CONTEXT_OPENGL_DEBUG, EGL_TRUE});
    attributes.push_back(EGL_NONE);
    EGLContext created =
        eglCreateContext(candidate, EGL_NO_CONFIG_KHR, EGL_NO_CONTEXT, attributes.data());
    if (created == EGL_NO_CONTEXT) return fail(failed("eglCreateContext(4.5 core)"));
    if (!eglMakeCurrent(candidate, EGL_NO_SURFACE, EGL_NO_SURFACE, created)) {
      std::string why = failed("eglMakeCurrent(no surface)");
      eglDestroyContext(candidate, created);
      return fail(why);
    }
    GLint glMajor = 0, glMinor = 0;
    glGetIntegerv(GL_MAJOR_VERSION, &glMajor);
    glGetIntegerv(GL_MINOR_VERSION, &glMinor);
    if (glMajor * 10 + glMinor < 45) {
      eglMakeCurrent(candidate, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
      eglDestroyContext(candidate, created);
      return fail("got OpenGL " + std::to_string(glMajor) + "." + std::to_string(glMinor));
    }
    keepDisplay(candidate);
    display = candidate;
    context = created;
    return true;
  }

  ~Egl() {
    if (context == EGL_NO_CONTEXT) return;
    eglMakeCurrent(display, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
    eglDestroyContext(display, context);
    eglReleaseThread();
  }
};

HeadlessContext::HeadlessContext(const ContextDesc& desc) : mEgl(std::make_unique<Egl>()) {
  std::vector<std::string> reasons;
  std::string reason;
  bool ok = librariesPresent(reason);
  if (!ok) reasons.push_back(reason);
  if (ok && !epoxy_has_egl_extension(EGL_NO_DISPLAY, "EGL_EXT_platform_base")) {
    ok = false;
    reasons.push_back("no EGL_EXT_platform_base");
  }
  bool current = false;
  if (ok && epoxy_has_egl_extension(EGL_NO_DISPLAY, "EGL_MESA_platform_surfaceless")) {
    EGLDisplay display =
        eglGetPlatformDisplayEXT(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
    if (mEgl->tryDisplay(display, desc, reason)) {
      current = true;
      mPlatform = "surfaceless";
    } else {
      reasons.push_back("surfaceless: " + reason);
    }
  } else if (ok) {
    reasons.push_back("no EGL_MESA_platform_surfaceless");
  }
  if (ok && !current) {
    if (epoxy_has_egl_extension(EGL_NO_DISPLAY, "EGL_EXT_device_enumeration") ||
        epoxy_has_egl_extension(EGL_NO_DISPLAY, "EGL_EXT_device_base")) {
      EGLint count = 0;
      eglQueryDevicesEXT(0, nullptr, &count);
      std::vector<EGLDeviceEXT> devices(static_cast<std::size_t>(count > 0 ? count : 0));
      if (count > 0) eglQueryDevicesEXT(count, devices.data(), &count);
      if (count <= 0) reasons.push_back("device: no EGL devices");
      for (EGLint i = 0; i < count && !current; ++i) {
        EGLDisplay display = eglGetPlatformDisplayEXT(
            EGL_PLATFORM_DEVICE_EXT, devices[static_cast<std::size_t>(i)], nullptr);
        if (mEgl->tryDisplay(display, desc, reason)) {
          current = true;
          mPlatform = "device " + std::to_string(i);
        } else {
          reasons.push_back("device " + std::to_string(i) + ": " + reason);
        }
      }
    } else {
      reasons.push_back("no EGL_EXT_device_enumeration");
    }
  }
  if (!current) {
    std::string message = "no usable OpenGL 4.5 core context through EGL (";
    for (std::size_t i = 0; i < reasons.size(); ++i) message += (i ? "; " : "") + reasons[i];
    throw GpuError(Diagnostic::ContextUnavailable, message + "); " + std::string(kInstallHint));
  }
  auto string = [](GLenum name) {
    const GLubyte* s = glGetString(name);
    return s ? std::string(reinterpret_cast<const char*>(s)) : std::string();
  };
  mRenderer = string(GL_RENDERER);
  mVendor = string(GL_VENDOR);
  mVersion = string(GL_VERSION);
  mGlslVersion = string(GL_SHADING_LANGUAGE_VERSION);
  mDebug = std::make_unique<DebugOutput>(desc.debugNotifications);
}

HeadlessContext::~HeadlessContext() {
  // The debug callback belongs to this context, which may not be current. A destructor must not
  // throw: when the context cannot be made current (lost, or current on another thread), the
  // callback is left to die with the context.
  eglBindAPI(EGL_OPENGL_API);
  if (eglMakeCurrent(mEgl->display, EGL_NO_SURFACE, EGL_NO_SURFACE, mEgl->context))
    mDebug.reset();
  else
    static_cast<void>(mDebug.release());
}

void HeadlessContext::makeCurrent() {
  eglBindAPI(EGL_OPENGL_API);  // the thread's API may have been reset by eglReleaseThread
  if (!eglMakeCurrent(mEgl->display, EGL_NO_SURFACE, EGL_NO_SURFACE, mEgl->context))
    throw GpuError(Diagnostic::ContextUnavailable, failed("eglMakeCurrent"));
}

}  // namespace prism::gpu
