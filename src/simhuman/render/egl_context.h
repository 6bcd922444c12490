#pragma once
/// A headless OpenGL context from EGL with no surface at all (no window, no pbuffer), for
/// rendering into framebuffer objects.

#include <memory>
#include <string>

#include "absl/status/status.h"
#include "absl/status/statusor.h"

namespace simhuman::render {

/// A desktop-OpenGL (compatibility profile) context on a headless EGL display, bound with
/// EGL_NO_SURFACE. Displays are tried in this order: Mesa's surfaceless platform
/// (EGL_MESA_platform_surfaceless), each device of the device platform
/// (EGL_EXT_platform_device), then the default display. The EGL display is shared by every
/// context of the process and terminated when the last one is destroyed, so contexts can be
/// created and destroyed any number of times.
///
/// Thread-safety: Create() may be called from any thread. The context is made current on the
/// creating thread; use and destroy it on that thread (EGL allows a context to be current in
/// only one thread at a time, and this class does not move it).
class EglContext {
 public:
  /// Creates the context and makes it current on the calling thread. Returns kUnavailable when
  /// no EGL display could give a context; the message names every display tried and why it
  /// failed.
  static absl::StatusOr<std::unique_ptr<EglContext>> Create();

  EglContext(const EglContext&) = delete;
  EglContext& operator=(const EglContext&) = delete;

  /// Releases the context (if current on this thread), destroys it, and terminates the display
  /// when no other EglContext uses it.
  ~EglContext();

  /// Makes this context current on the calling thread (a no-op when it already is).
  absl::Status MakeCurrent();

  /// True when this context is current on the calling thread.
  bool IsCurrent() const;

  /// Which display was used, e.g. "surfaceless", "device 0", "default".
  const std::string& platform() const { return platform_; }

  /// The GL_RENDERER string, e.g. "llvmpipe (LLVM 15.0.6, 256 bits)".
  const std::string& gl_renderer() const { return gl_renderer_; }

 private:
  EglContext() = default;

  void* display_ = nullptr;  // EGLDisplay
  void* context_ = nullptr;  // EGLContext
  std::string platform_;
  std::string gl_renderer_;
};

}  // namespace simhuman::render
