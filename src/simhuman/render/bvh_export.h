#pragma once
/// BVH export of a humanoid's motion (docs/FORMATS.md "BVH export"): our skeleton as BVH
/// joints (pelvis = Hips, torso = Spine, head, arms, legs, hands and feet), the hinges of each
/// body as that joint's three rotation channels, the root's position and rotation. Y up and
/// facing +Z (the CMU/Blender convention), metres. Round-trips through learn/bvh.h's
/// importer: every hinge comes back within a small fraction of a degree.
///
/// Lives in render/ beside the other writers of recorded motion; it needs only the compiled
/// model (world), not the importer.

#include <mujoco/mujoco.h>

#include <string>
#include <vector>

#include "simhuman/core/status.h"
#include "simhuman/world/sim_world.h"

namespace simhuman::render {

/// Recorded motion: qpos rows of one model with their times (seconds, non-decreasing).
struct QposFrames {
  std::vector<double> time_s;
  std::vector<std::vector<double>> qpos;  ///< each m->nq long
};

/// The qpos at time t_s (clamped to the recording): the row recorded within 0.1 ms of t_s (the
/// precision of trajectory.csv's times), else linear interpolation between the two neighbouring
/// rows, free and ball joints' quaternions renormalised.
std::vector<double> SampleQpos(const mjModel* m, const QposFrames& frames, double t_s);

/// The BVH joint names, in file order (Hips first; End Sites not listed).
const std::vector<std::string>& BvhExportJointNames();

/// BVH text of `agent`'s motion in `frames`, sampled every 1/fps seconds from the first
/// recorded time to the last. Joint offsets come from the compiled model (so a child's
/// skeleton is smaller); the toe End Sites lie at the standing floor level. Errors:
/// InvalidArgument for fps outside (0, 1000], no frames, a row whose size is not m->nq;
/// Internal when the model's hinges are not along body axes in x, y, z order.
core::StatusOr<std::string> AgentBvh(const mjModel* m, const world::AgentIndex& agent,
                                     const QposFrames& frames, double fps);

}  // namespace simhuman::render
