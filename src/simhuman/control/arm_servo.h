#pragma once
/// One small piece both the MPC's hand servo and the carry grip use: the damped least-squares
/// change of one arm's four joints (shoulder x, y, z and elbow) that moves its hand by a given
/// vector, from the Jacobian of the current pose. Torch-free, MuJoCo-only.

#include <mujoco/mujoco.h>

#include <Eigen/Core>
#include <array>

#include "simhuman/core/status.h"
#include "simhuman/world/sim_world.h"

namespace simhuman::control {

/// The actuator-order indices of each arm's joints: [0] right, [1] left; each shoulder x, y,
/// z, elbow. InternalError when the humanoid lacks one (naming it).
core::StatusOr<std::array<std::array<int, 4>, 2>> ArmJointIndices();

/// The arm joint change (the four joints of `arm`, in that order) that moves site `site` by
/// `miss`, damped least squares with damping `damping` (m). `d` must hold the pose's
/// kinematics and com positions (what mj_step or mj_kinematics + mj_comPos leave).
Eigen::Vector4d ArmStepToward(const mjModel* m, const mjData* d, const world::AgentIndex& a,
                              const std::array<int, 4>& arm, int site, const Eigen::Vector3d& miss,
                              double damping = 0.05);

}  // namespace simhuman::control
