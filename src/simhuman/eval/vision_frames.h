#pragma once
/// Egocentric frames of DASH's tabletop scenes with what they truly show, for training and
/// scoring the vision module (issue 16): frames at task planning (a generated scene as it
/// starts, the head turned to the object region) and frames while placing or stacking (the
/// pick-and-place pipeline running, the head turned to the destination, the object in the hand
/// above it).

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "simhuman/core/status.h"
#include "simhuman/perceive/vision/head_camera.h"
#include "simhuman/perceive/vision/vision_data.h"

namespace simhuman::eval {

/// One frame and its truth.
struct VisionFrame {
  std::string stage;  ///< "planning", "placing" or "stacking"
  uint64_t scene_seed = 0;
  std::vector<uint8_t> rgb;
  std::vector<int> body_ids;  ///< per pixel (OffscreenRenderer::RenderBodyIds)
  perceive::PinholeCamera camera;
  std::vector<perceive::ObjectTruth> truth;  ///< with pixel counts of this frame
  int task_object = -1;                      ///< index into truth of the object being moved
  double render_s = 0;                       ///< the RGB render's own time
};

struct VisionFrameOptions {
  int width = 160, height = 120;
  double fovy_deg = 60;
  /// Scenes at task planning, and frames of each (the gaze jittered by up to gaze_jitter_m)
  int planning_scenes = 100;
  int planning_views = 1;
  /// Pick-and-place episodes whose placing/stacking stage (the object lifted and within
  /// placing_near_m of its destination, horizontally) is sampled every placing_every_s (at most
  /// placing_frames per episode); the scripted grasp
  int placing_episodes = 50;
  int placing_frames = 8;
  double placing_every_s = 0.15;
  double placing_near_m = 0.08;
  double gaze_jitter_m = 0.05;
  /// DASH's 2 cm position noise: the gaze during placing aims at the destination moved by up to
  /// this much, as the estimate it is computed from would be
  double position_noise_m = 0.02;
  /// A share of the placing/stacking frames show the held object turned in the hand by a
  /// random tilt of up to held_tilt_max_deg (about a horizontal axis through the palm point):
  /// objects tip in the grip by 3-30 degrees, and the up axis must be read from how they look
  /// (the scripted grasps alone leave most of them near upright). 0: none.
  double held_tilt_share = 0;
  double held_tilt_max_deg = 30;
  uint64_t seed = 1;
  /// Seed stream: training and evaluation draw disjoint scenes
  uint64_t stream = 0;
};

/// Calls `on_frame` for each frame: first the planning frames, then the placing/stacking ones.
/// Errors: the renderer (no EGL), the scene generator.
core::Status CollectVisionFrames(const VisionFrameOptions& options,
                                 const std::function<void(VisionFrame&)>& on_frame);

}  // namespace simhuman::eval
