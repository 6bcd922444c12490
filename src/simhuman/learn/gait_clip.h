#pragma once
/// A kinematic clip of the walking task's procedural reference gait
/// (control::WalkReference): the pelvis advances along +x at the commanded speed, level, at the
/// height that puts the lower foot on the floor; the gait clock runs at the task's period.
/// Torch-free (compiles the humanoid model to place the feet).

#include "simhuman/control/policy/walk_task.h"
#include "simhuman/core/status.h"
#include "simhuman/learn/motion_clip.h"

namespace simhuman::learn {

/// Options of GaitClip.
struct GaitClipOptions {
  double seconds = 10;   ///< clip length, s (0, 3600]
  double fps = 30;       ///< frame rate (0, 1000]
  double speed_mps = 1;  ///< forward speed command (vx), m/s, in [-0.4, vmax]
  control::WalkParams params;
  absl::Status Validate() const;
};

/// The reference gait as a clip (amplitude 1, phase from 0). InvalidArgument on bad options.
core::StatusOr<MotionClip> GaitClip(const GaitClipOptions& options);

}  // namespace simhuman::learn
