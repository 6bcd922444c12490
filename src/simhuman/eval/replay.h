#pragma once
/// Rendering a recorded episode after the fact: the trajectory's qpos replayed through
/// mj_kinematics into a video and a contact sheet, from a camera that follows the human(s).

#include <string>

#include "absl/status/status.h"
#include "simhuman/control/runner.h"
#include "simhuman/plan/contact_chain.h"
#include "simhuman/world/sim_world.h"

namespace simhuman::eval {

/// What RenderReplay() writes and how.
struct ReplayOptions {
  std::string video_path;  ///< MP4 at the trajectory's fps; empty: no video
  std::string sheet_path;  ///< PNG contact sheet; empty: no sheet
  int width = 640;         ///< frame size, pixels
  int height = 480;
  int sheet_frames = 12;  ///< frames on the sheet, evenly spaced (fewer if fewer recorded)
  int sheet_cols = 4;
  int sheet_downscale = 2;
  /// Camera: render::AutoCamera (every human framed, their body points kept out of
  /// occlusion, a front-side view preferred) when true; else a fixed side-front view
  /// `side_angle_deg` off the first human's starting facing at `elevation_deg`.
  bool auto_camera = true;
  double side_angle_deg = 45.0;
  double elevation_deg = -15.0;
  double margin = 1.3;    ///< FrameBodies margin
  double smooth_s = 0.6;  ///< CameraSmoother time constant
  int font_scale = 150;   ///< caption size (render::RendererOptions::font_scale)
  bool sky = true;        ///< a daylight sky instead of black (render::RendererOptions::sky)
  bool shadows = false;   ///< shadows from the scene's lights (several times slower)
};

/// Replays `trajectory` (recorded by control::RunEpisode on `world`) into the files of
/// `options`, with the caption "step i/n <step text> t=<time> s". Renders on the calling
/// thread, with its own mjData (world.data() is not touched). Both outputs are attempted: when
/// the video cannot be written (no ffmpeg) the sheet still is, and the first error is returned.
/// Errors: kInvalidArgument for an empty trajectory or a qpos size that does not match the
/// model; kUnavailable when there is no EGL display (nothing is written); the renderer's,
/// VideoWriter's and WritePng's errors otherwise.
absl::Status RenderReplay(const world::SimWorld& world, const plan::ContactChain& chain,
                          const control::Trajectory& trajectory, const ReplayOptions& options);

}  // namespace simhuman::eval
