#pragma once
/// Where the carry's walking phases aim a walking policy (control/policy/carry_task.h): the
/// approach's line into the stand point, the carry's target re-aimed at the destination, and
/// when the held box has reached it. Torch-free, MuJoCo-only.

#include <mujoco/mujoco.h>

#include <Eigen/Core>

#include "simhuman/control/policy/carry_task.h"

namespace simhuman::control {

/// Sets the phase's stand point `xy` and heading `yaw`; the walker aims `lead` past the stand
/// point (a walking policy stops short of its target).
void SetCarryWalkTarget(CarryState* s, const Eigen::Vector2d& xy, double yaw,
                        const Eigen::Vector2d& lead = Eigen::Vector2d::Zero());

/// The approach's walking target: the stand point (and its lead) once the human is on the line
/// that ends there along the facing direction, else the start of that line.
void SteerApproach(const CarryParams& p, const mjData* d, const CarryIndex& ix, CarryState* s);

/// The carry's stand point and walking target from the pelvis at `pelvis` and the held box's
/// centre at `box` (re-aimed at the destination; `entering`: the carry's first step).
void SteerCarry(const Eigen::Vector2d& pelvis, const Eigen::Vector2d& box, bool entering,
                CarryState* s);

/// Whether the held box has come to the destination (the put-down starts).
bool CarryReachedDestination(const CarryParams& p, const CarryBox& box, const CarryState& s);

}  // namespace simhuman::control
