#include "simhuman/render/egl_context.h"

// keep Xlib out: its macros (Status, None, Bool) clash with absl and friends
#define EGL_NO_X11
#define MESA_EGL_NO_X11_HEADERS
#include <EGL/egl.h>
#include <EGL/eglext.h>
#include <GL/gl.h>

#include <cstdio>
#include <map>
#include <mutex>
#include <string>
#include <vector>

#include "absl/strings/str_cat.h"
#include "absl/strings/str_join.h"

namespace simhuman::render {
namespace {

// EGL_EXT_device_enumeration, looked up at run time
using QueryDevicesFn = EGLBoolean (*)(EGLint, EGLDeviceEXT*, EGLint*);

// how many EglContexts use each initialized display; guarded by DisplayMutex()
std::mutex& DisplayMutex() {
  static std::mutex mutex;
  return mutex;
}
std::map<EGLDisplay, int>& DisplayUsers() {
  static auto* users = new std::map<EGLDisplay, int>();
  return *users;
}

// initializes `dpy` (if no one else has) and counts one more user
bool AcquireDisplay(EGLDisplay dpy) {
  std::lock_guard<std::mutex> lock(DisplayMutex());
  int& users = DisplayUsers()[dpy];
  if (users == 0) {
    EGLint major = 0, minor = 0;
    if (eglInitialize(dpy, &major, &minor) != EGL_TRUE) {
      DisplayUsers().erase(dpy);
      return false;
    }
  }
  ++users;
  return true;
}

// counts one user less and terminates the display after its last user
void ReleaseDisplay(EGLDisplay dpy) {
  std::lock_guard<std::mutex> lock(DisplayMutex());
  auto it = DisplayUsers().find(dpy);
  if (it == DisplayUsers().end()) return;
  if (--it->second == 0) {
    DisplayUsers().erase(it);
    eglTerminate(dpy);
  }
}

std::string EglErrorName(EGLint error) {
  switch (error) {
    case EGL_SUCCESS:
      return "EGL_SUCCESS";
    case EGL_NOT_INITIALIZED:
      return "EGL_NOT_INITIALIZED";
    case EGL_BAD_ACCESS:
      return "EGL_BAD_ACCESS";
    case EGL_BAD_ALLOC:
      return "EGL_BAD_ALLOC";
    case EGL_BAD_ATTRIBUTE:
      return "EGL_BAD_ATTRIBUTE";
    case EGL_BAD_CONFIG:
      return "EGL_BAD_CONFIG";
    case EGL_BAD_CONTEXT:
      return "EGL_BAD_CONTEXT";
    case EGL_BAD_CURRENT_SURFACE:
      return "EGL_BAD_CURRENT_SURFACE";
    case EGL_BAD_DISPLAY:
      return "EGL_BAD_DISPLAY";
    case EGL_BAD_MATCH:
      return "EGL_BAD_MATCH";
    case EGL_BAD_NATIVE_PIXMAP:
      return "EGL_BAD_NATIVE_PIXMAP";
    case EGL_BAD_NATIVE_WINDOW:
      return "EGL_BAD_NATIVE_WINDOW";
    case EGL_BAD_PARAMETER:
      return "EGL_BAD_PARAMETER";
    case EGL_BAD_SURFACE:
      return "EGL_BAD_SURFACE";
    case EGL_CONTEXT_LOST:
      return "EGL_CONTEXT_LOST";
    default: {
      char buf[32];
      std::snprintf(buf, sizeof(buf), "EGL error 0x%04x", static_cast<unsigned>(error));
      return buf;
    }
  }
}

bool HasExtension(const char* extensions, const std::string& name) {
  if (extensions == nullptr) return false;
  const std::string list = std::string(" ") + extensions + " ";
  return list.find(" " + name + " ") != std::string::npos;
}

struct Candidate {
  std::string name;
  EGLDisplay display;
};

// tries to get a current, surfaceless desktop-GL context on `dpy`; on success the display
// stays acquired and *ctx holds the context
absl::Status TryDisplay(EGLDisplay dpy, EGLContext* ctx) {
  if (dpy == EGL_NO_DISPLAY) return absl::UnavailableError("no display");
  if (!AcquireDisplay(dpy)) {
    return absl::UnavailableError(absl::StrCat("eglInitialize: ", EglErrorName(eglGetError())));
  }
  auto fail = [dpy](const std::string& what) {
    const std::string msg = absl::StrCat(what, ": ", EglErrorName(eglGetError()));
    ReleaseDisplay(dpy);
    return absl::UnavailableError(msg);
  };
  const char* display_extensions = eglQueryString(dpy, EGL_EXTENSIONS);
  if (!HasExtension(display_extensions, "EGL_KHR_surfaceless_context")) {
    ReleaseDisplay(dpy);
    return absl::UnavailableError("display lacks EGL_KHR_surfaceless_context");
  }
  if (eglBindAPI(EGL_OPENGL_API) != EGL_TRUE) return fail("eglBindAPI(EGL_OPENGL_API)");

  // a config is only needed for its GL capabilities: the context never gets a surface
  const EGLint config_attribs[] = {EGL_RED_SIZE,
                                   8,
                                   EGL_GREEN_SIZE,
                                   8,
                                   EGL_BLUE_SIZE,
                                   8,
                                   EGL_ALPHA_SIZE,
                                   8,
                                   EGL_DEPTH_SIZE,
                                   24,
                                   EGL_STENCIL_SIZE,
                                   8,
                                   EGL_RENDERABLE_TYPE,
                                   EGL_OPENGL_BIT,
                                   EGL_NONE};
  EGLConfig config = nullptr;
  EGLint num_configs = 0;
  if (eglChooseConfig(dpy, config_attribs, &config, 1, &num_configs) != EGL_TRUE ||
      num_configs < 1) {
    if (!HasExtension(display_extensions, "EGL_KHR_no_config_context")) {
      return fail("eglChooseConfig found no RGBA8/depth24 desktop-GL config");
    }
    config = EGL_NO_CONFIG_KHR;
  }
  EGLContext context = eglCreateContext(dpy, config, EGL_NO_CONTEXT, nullptr);
  if (context == EGL_NO_CONTEXT) return fail("eglCreateContext");
  if (eglMakeCurrent(dpy, EGL_NO_SURFACE, EGL_NO_SURFACE, context) != EGL_TRUE) {
    const std::string msg =
        absl::StrCat("eglMakeCurrent(EGL_NO_SURFACE): ", EglErrorName(eglGetError()));
    eglDestroyContext(dpy, context);
    ReleaseDisplay(dpy);
    return absl::UnavailableError(msg);
  }
  *ctx = context;
  return absl::OkStatus();
}

}  // namespace

absl::StatusOr<std::unique_ptr<EglContext>> EglContext::Create() {
  const char* client_extensions = eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS);
  auto get_platform_display = reinterpret_cast<PFNEGLGETPLATFORMDISPLAYEXTPROC>(
      eglGetProcAddress("eglGetPlatformDisplayEXT"));
  const bool has_platform_base =
      get_platform_display != nullptr && HasExtension(client_extensions, "EGL_EXT_platform_base");

  std::vector<std::string> failures;
  auto try_candidate = [&](const std::string& name, EGLDisplay dpy) -> std::unique_ptr<EglContext> {
    EGLContext context = EGL_NO_CONTEXT;
    const absl::Status status = TryDisplay(dpy, &context);
    if (!status.ok()) {
      failures.push_back(absl::StrCat(name, " (", status.message(), ")"));
      return nullptr;
    }
    std::unique_ptr<EglContext> out(new EglContext());
    out->display_ = dpy;
    out->context_ = context;
    out->platform_ = name;
    const auto* renderer = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
    out->gl_renderer_ = renderer != nullptr ? renderer : "unknown";
    return out;
  };

  // 1. Mesa's surfaceless platform: no X, no DRM device needed (llvmpipe works)
  if (!has_platform_base) {
    failures.push_back("surfaceless (no EGL_EXT_platform_base)");
  } else if (!HasExtension(client_extensions, "EGL_MESA_platform_surfaceless")) {
    failures.push_back("surfaceless (no EGL_MESA_platform_surfaceless)");
  } else {
    EGLDisplay dpy =
        get_platform_display(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
    if (auto ctx = try_candidate("surfaceless", dpy)) return ctx;
  }

  // 2. the device platform: one display per GPU (or software) device
  auto query_devices = reinterpret_cast<QueryDevicesFn>(eglGetProcAddress("eglQueryDevicesEXT"));
  if (!has_platform_base || query_devices == nullptr ||
      !HasExtension(client_extensions, "EGL_EXT_platform_device")) {
    failures.push_back("device (no EGL_EXT_platform_device / eglQueryDevicesEXT)");
  } else {
    EGLDeviceEXT devices[16];
    EGLint num_devices = 0;
    if (query_devices(16, devices, &num_devices) != EGL_TRUE || num_devices == 0) {
      failures.push_back(absl::StrCat(
          "device (eglQueryDevicesEXT found no device: ", EglErrorName(eglGetError()), ")"));
    }
    for (EGLint i = 0; i < num_devices; ++i) {
      EGLDisplay dpy = get_platform_display(EGL_PLATFORM_DEVICE_EXT, devices[i], nullptr);
      if (auto ctx = try_candidate(absl::StrCat("device ", i), dpy)) return ctx;
    }
  }

  // 3. whatever the default display is (needs X or Wayland on most systems)
  if (auto ctx = try_candidate("default", eglGetDisplay(EGL_DEFAULT_DISPLAY))) return ctx;

  return absl::UnavailableError(
      absl::StrCat("no EGL display gave an OpenGL context; tried: ", absl::StrJoin(failures, "; "),
                   ". Install the Debian packages libegl1, libegl-mesa0 and libgl1-mesa-dri"));
}

EglContext::~EglContext() {
  auto dpy = static_cast<EGLDisplay>(display_);
  auto ctx = static_cast<EGLContext>(context_);
  if (eglGetCurrentContext() == ctx) {
    eglMakeCurrent(dpy, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
  }
  eglDestroyContext(dpy, ctx);
  ReleaseDisplay(dpy);
}

absl::Status EglContext::MakeCurrent() {
  if (IsCurrent()) return absl::OkStatus();
  if (eglMakeCurrent(static_cast<EGLDisplay>(display_), EGL_NO_SURFACE, EGL_NO_SURFACE,
                     static_cast<EGLContext>(context_)) != EGL_TRUE) {
    return absl::FailedPreconditionError(
        absl::StrCat("eglMakeCurrent failed (", EglErrorName(eglGetError()),
                     "); is the context current on another thread?"));
  }
  return absl::OkStatus();
}

bool EglContext::IsCurrent() const { return eglGetCurrentContext() == context_; }

}  // namespace simhuman::render
