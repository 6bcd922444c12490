#pragma once
/// A transport as a person makes it: the hand lifts what it holds, carries it over whatever
/// stands between on an arc, and lowers it onto its goal, the palm on a smooth curve in the
/// world rather than a joint-space path that may swing round the body.

#include <mujoco/mujoco.h>

#include <Eigen/Core>
#include <vector>

#include "simhuman/control/manip/reach.h"
#include "simhuman/core/status.h"

namespace simhuman::control::manip {

/// Settings of PlanCarryOver.
struct CarryOverOptions {
  /// The arc's top this far above the higher of its two ends (m), tried in turn until one path
  /// is free
  std::vector<double> lift_m = {0.05, 0.09, 0.13, 0.18, 0.24};
  /// Once an arc is free, one this much higher is taken when it is free too: the tracked arm
  /// sags a few centimetres below its plan with a load in the hand
  double margin_m = 0.04;
  double step_m = 0.02;  ///< palm poses this far apart along the arc (at most)
  /// The hand may turn this far (rad) from the arc's orientation on the way (ArmAlongOptions::
  /// via_tol_rot_rad): an arm whose shoulder or wrist stands at its limit after the grasp
  /// cannot lift the object without tilting it a little, as a person's cannot
  double tilt_tol_rad = 0.15;
};

/// The palm poses that carry a held object over an arc from where the hand holds it at `from`
/// to where it holds it at `to` (from excluded, `to` last). `held` is a point of the object
/// (e.g. its base) in the hand's frame, measured from the palm point. The point follows a cubic
/// Bezier whose two inner control points stand over each end at the height that puts the
/// curve's top `lift_m` above the higher end, so that it leaves and arrives vertically; the
/// hand's orientation turns from one end's to the other's along the way (slerp). At most
/// `step_m` apart.
std::vector<PalmPose> OverArcPalmPath(const PalmPose& from, const PalmPose& to,
                                      const Eigen::Vector3d& held, double lift_m, double step_m);

/// Plans the arm from its pose in `d` (the palm at `from`) over an arc to `goal`
/// (OverArcPalmPath, PlanArmAlong): the lowest free arc of `co.lift_m`, raised by co.margin_m
/// when that is free too. With `goal_q` (e.g. the arm angles a searched plan ends in at
/// `goal`), the posture moves toward them on the way (ArmAlongOptions::rest_to). Errors:
/// InvalidArgument for an empty `co.lift_m`; otherwise the last arc's plan failure
/// (FailedPrecondition or NotFound, PlanArmAlong's).
core::StatusOr<ArmMotion> PlanCarryOver(const mjModel* m, const mjData* d, mjData* scratch,
                                        const ArmChain& arm, const PalmPose& from,
                                        const PalmPose& goal, const Eigen::Vector3d& held,
                                        const CarryOverOptions& co,
                                        const ArmMotionOptions& options = {},
                                        const Eigen::VectorXd& goal_q = {});

}  // namespace simhuman::control::manip
