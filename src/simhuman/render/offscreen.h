#pragma once
/// Headless rendering of a MuJoCo scene into RGB images (EGL + MuJoCo's OpenGL renderer).

#include <mujoco/mujoco.h>

#include <cstdint>
#include <memory>
#include <string>
#include <string_view>
#include <thread>
#include <vector>

#include "absl/status/status.h"
#include "absl/status/statusor.h"
#include "simhuman/render/camera.h"

namespace simhuman::render {

class EglContext;

/// Options of an OffscreenRenderer. Shadows and reflections are off by default: on Mesa's
/// llvmpipe (2 cores, 480x480, MuJoCo's humanoid) they cost ~5x. 4x MSAA (MuJoCo's default
/// offsamples) costs ~2x: ~50 frames/s with it, ~105 with msaa_samples = 0.
struct RendererOptions {
  bool shadows = false;      // mjRND_SHADOW
  bool reflections = false;  // mjRND_REFLECTION (reflective floors)
  bool skybox = false;       // mjRND_SKYBOX; when off the background is black
  /// Paint the background (pixels nothing was drawn on) with a daylight sky, blue overhead and
  /// pale at the horizon, by the elevation of each pixel's view ray; costs one extra readback
  /// and redraw per frame when there is a caption.
  bool sky = false;
  /// Multisample anti-aliasing samples; -1 keeps the model's m->vis.quality.offsamples
  /// (4 unless the model says otherwise), 0 is fastest. Clamped to GL_MAX_SAMPLES.
  int msaa_samples = -1;
  /// Caption font size as a mjtFontScale percentage (50, 100, 150, 200, 250, 300); 0 picks one
  /// from the image height.
  int font_scale = 0;
  /// Vertical field of view of free cameras (degrees); 0 keeps the model's m->vis.global.fovy.
  double fovy_deg = 0;
  /// Capacity of the abstract scene, in geoms (model geoms plus decorations).
  int max_geoms = 10000;

  /// Checks the ranges above; the message names the field.
  absl::Status Validate() const;
};

/// Renders a MuJoCo model headlessly (no X display) into tightly packed RGB8 images.
///
/// Create() takes a snapshot of the model (mj_copyModel, with the offscreen buffer sized to the
/// image); later edits of the caller's model (colours, sizes) are not seen. Every
/// mjData passed to Render() must belong to a model with the same sizes as that snapshot.
///
/// Thread-safety: the renderer owns an OpenGL context that lives on the thread that called
/// Create(). Call Render() and destroy the renderer on that same thread; Render() from another
/// thread returns kFailedPrecondition. Several renderers may exist at once, and renderers may
/// be created and destroyed any number of times in one process.
class OffscreenRenderer {
 public:
  /// Creates an EGL context (surfaceless, then device, then default display), and MuJoCo's
  /// render context for a `width` x `height` image. Errors: kInvalidArgument for bad sizes or
  /// options (or sizes beyond the GL limits), kUnavailable when no EGL display works (the
  /// message names each display tried) or its OpenGL lacks what MuJoCo needs.
  static absl::StatusOr<std::unique_ptr<OffscreenRenderer>> Create(
      const mjModel* m, int width, int height, const RendererOptions& options = {});

  OffscreenRenderer(const OffscreenRenderer&) = delete;
  OffscreenRenderer& operator=(const OffscreenRenderer&) = delete;
  ~OffscreenRenderer();

  /// Renders the state in `d` (positions from mj_kinematics or mj_forward) from `cam` into
  /// `rgb`: width*height*3 bytes, row-major, top row first. A non-empty `caption` is drawn in
  /// the top-left corner (newlines start new lines). `d` is not modified, but must not be
  /// stepped by another thread during the call. Errors: kFailedPrecondition on the wrong
  /// thread, kResourceExhausted when the scene needs more than options.max_geoms geoms (MuJoCo
  /// then also counts a mjWARN_VGEOMFULL warning in d), kInternal on an OpenGL error.
  absl::Status Render(const mjData* d, const CameraSpec& cam, std::vector<uint8_t>* rgb,
                      std::string_view caption = {});

  /// Renders which body each pixel shows, into `body_ids` (width*height, row-major, top row
  /// first; -1 where no geom of a body was drawn: the background, decorations). Uses MuJoCo's
  /// segmentation mode (mjRND_SEGMENT with mjRND_IDCOLOR), so no lighting or caption; with
  /// multisampling an edge pixel can blend two ids and decode to -1 or to a neighbour's id, so
  /// create the renderer with msaa_samples = 0 when exact edges matter. Errors as Render().
  absl::Status RenderBodyIds(const mjData* d, const CameraSpec& cam, std::vector<int>* body_ids);

  /// Replaces the model snapshot (as Create() took it), keeping the OpenGL context: much cheaper
  /// than a new renderer when the scene changes (Mesa compiles its shaders once per context).
  /// Errors: kFailedPrecondition on the wrong thread, kInternal on an OpenGL error.
  absl::Status SetModel(const mjModel* m);

  /// MuJoCo's visualization options (what to draw: contact points, joints, sites, groups...).
  /// Defaults are mjv_defaultOption's.
  mjvOption& vis_options() { return vis_options_; }

  int width() const { return width_; }
  int height() const { return height_; }

  /// The renderer's model snapshot (owned by the renderer).
  const mjModel* model() const { return model_; }

  /// Which EGL display is used ("surfaceless", "device 0", "default").
  const std::string& egl_platform() const;

  /// The OpenGL renderer string, e.g. "llvmpipe (LLVM 15.0.6, 256 bits)".
  const std::string& gl_renderer() const;

 private:
  OffscreenRenderer() = default;

  int width_ = 0;
  int height_ = 0;
  RendererOptions options_;
  std::thread::id owner_thread_;
  std::unique_ptr<EglContext> egl_;
  mjModel* model_ = nullptr;  // owned snapshot
  mjvScene scene_;
  mjvOption vis_options_;
  mjrContext context_;
  bool scene_made_ = false;
  bool context_made_ = false;
  std::vector<uint8_t> bottom_up_;  // readback scratch
  std::vector<float> depth_;        // readback scratch (sky)

  // copies `m` into model_ and makes the scene and MuJoCo's render context for it
  absl::Status LoadModel(const mjModel* m, int max_samples);
  // makes the context current and draws the scene from `d` seen by `cam` into the offscreen
  // buffer: lit (options_) or, with `segment`, each geom in its segmentation id colour
  absl::Status DrawScene(const mjData* d, const CameraSpec& cam, bool segment);
};

}  // namespace simhuman::render
