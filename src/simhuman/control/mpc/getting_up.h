#pragma once
/// Getting up from lying on a bed, as a person does it: curl the trunk up (spine and neck
/// flexed, arms reaching toward the knees, so the trunk's weight acts close to the hips and the
/// straight legs on the mattress outweigh it), sit up with the legs along the bed, then swing
/// the legs over the bed's front edge and sit there; the rise from the edge is the rise from any
/// seat. Flexing the hips from flat on the back lifts the lighter legs instead of the trunk
/// (session 31 of docs/BENCHMARKS.md), which is why the curl comes first.

#include <mujoco/mujoco.h>

#include <optional>
#include <vector>

#include "simhuman/control/mpc/reference_pose.h"
#include "simhuman/control/task.h"
#include "simhuman/core/span.h"

namespace simhuman::control {

/// True when the trunk (pelvis to head) is more than `deg` degrees from upright.
bool TrunkTiltedMoreThan(core::Span<const Eigen::Vector3d> body_points, double deg);

/// For a step that stands up (stand or lean posture) from an object with a mattress: the task
/// of sitting on the mattress's front edge that comes first. Nothing for other steps.
std::optional<StepTask> EdgeSitBeforeRising(const StepTask& task, double scale);

/// `edge_sit` (a pose solved for EdgeSitBeforeRising's task, which sits where lying down
/// started) moved along the bed's front edge to where the pelvis `pelvis_now` (world) lies, at
/// least 0.2 m from the mattress's ends: a human gets up where it lies, not where it lay down.
void SitWhereLying(const StepTask& edge_sit_task, const Eigen::Vector3d& pelvis_now,
                   ReferencePose* edge_sit);

/// The legs hang over an edge: both feet more than 0.3 m x `scale` below the pelvis.
bool LegsHangDown(core::Span<const Eigen::Vector3d> body_points, double scale);

/// Keyframes from the current pose of agent `agent` in `d`, lying on its back, to sitting up on
/// the mattress with the legs along it: a curl, then the trunk upright over the hips, which stay
/// where they are. Empty when the pelvis is less than 45 degrees from upright about its own
/// left-right axis (sitting, or lying on the side). `scratch` is an mjData of the same model
/// that is overwritten.
std::vector<ReferencePose> SitUpKeys(const world::SimWorld& world, int agent, const mjData* d,
                                     mjData* scratch);

}  // namespace simhuman::control
