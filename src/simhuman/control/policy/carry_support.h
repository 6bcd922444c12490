#pragma once
/// Quasi-static support for the carry's squats (lift and put-down), a model-based alternative to
/// a learned residual: the joint torques that hold the human's current pose against gravity and
/// the load it holds, borne by its feet, added to the PD servos as a feedforward (a target
/// offset of torque / kp), so the knees no longer sag under the body; and an ankle strategy that
/// keeps the centre of mass over the feet. Measured with the carry probe (docs/BENCHMARKS.md,
/// issue 17, session 39). Torch-free.

#include <mujoco/mujoco.h>

#include <Eigen/Core>

#include "simhuman/control/policy/carry_task.h"

namespace simhuman::control {

/// Torques per hinge (kWalkActDim, actuator order, N m) of agent `ix` that hold its pose still:
/// the bias forces (d->qfrc_bias: gravity at the current pose) plus the load other bodies (not
/// the floor) put on it, taken as the sum of their contact forces borne half by each hand (a
/// squeeze on the box, or a knee pushing it, is no load to hold up: compensating it would press
/// harder and harder), with what the floating base needs put on the feet that touch the floor
/// (both when neither does) as the least-norm foot wrenches (a foot torque counts as a force
/// 0.2 m off). Reads the kinematics and contacts of the last mj_step or mj_forward.
void StaticSupportTorques(const mjModel* m, const mjData* d, const CarryIndex& ix, double* tau);

/// Adds `tau` / kp (each hinge's position-servo gain) to the targets `ctrl28`, within the
/// controls' range.
void AddSupportToTargets(const mjModel* m, const CarryIndex& ix, const double* tau, double* ctrl28);

/// Ankle strategy: moves both ankles' pitch targets in `ctrl28` so that the body, turning about
/// the ankles with the feet flat, brings the human's centre of mass back over the middle of the
/// feet: the offset turns `gain` of the horizontal error, the error taken `damping_s` ahead at
/// the centre of mass's velocity. Calls mj_subtreeVel on `d`.
void BalanceAnkles(const mjModel* m, mjData* d, const CarryIndex& ix, double gain, double damping_s,
                   double* ctrl28);

}  // namespace simhuman::control
