#pragma once
/// AMP state features of our humanoid (as in AMP, UniHSI and CooHOI), computed the same way
/// from a simulation state (mjData) and from a motion clip (qpos from the frame, velocities by
/// finite differences, then mj_kinematics). Torch-free.
///
/// Layout (kAmpFeatureDim = 84 floats; "heading frame" = world rotated by the pelvis yaw):
///   [0]      root (pelvis) height, m
///   [1, 4)   pelvis x axis (tangent) in the heading frame
///   [4, 7)   pelvis z axis (normal) in the heading frame
///   [7, 10)  root linear velocity in the heading frame, m/s
///   [10, 13) root angular velocity in the heading frame, rad/s
///   [13, 41) 28 hinge angles, rad (actuator order)
///   [41, 69) 28 hinge velocities, rad/s
///   [69, 84) key body origins relative to the pelvis in the heading frame, m: left hand,
///            right hand, left foot, right foot, head.
/// Thread-safety: pure functions of their arguments.

#include <mujoco/mujoco.h>

#include <vector>

#include "simhuman/core/status.h"
#include "simhuman/learn/motion_clip.h"
#include "simhuman/world/sim_world.h"

namespace simhuman::learn {

inline constexpr int kAmpFeatureDim = 13 + 2 * world::kHumanoidDofs + 15;

/// Writes the features of agent `a` in `d` to `out` (kAmpFeatureDim floats). Needs positions
/// (mj_kinematics or later) of the current qpos; velocities are read from qvel.
void AmpFeatures(const mjModel* m, const mjData* d, const world::AgentIndex& a, float* out);

/// Sets agent `a`'s qpos from clip frame `f` and its qvel from central differences of the
/// neighbouring frames (one-sided at the ends). Other entries of qpos/qvel are left alone.
void SetStateFromClip(const mjModel* m, const world::AgentIndex& a, const MotionClip& clip,
                      size_t f, mjtNum* qpos, mjtNum* qvel);

/// Features of every frame of `clip` as it is (no resampling): [frames x kAmpFeatureDim],
/// row-major. Uses a scratch mjData of `m`.
std::vector<float> ClipAmpFeatures(const mjModel* m, const world::AgentIndex& a,
                                   const MotionClip& clip);

}  // namespace simhuman::learn
