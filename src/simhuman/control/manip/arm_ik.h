#pragma once
/// The 7-DoF human arm of a dexterous-hand humanoid (world/hand.h) as a kinematic chain:
/// addresses, limits, collision checks of the arm against the scene, and inverse kinematics of
/// the palm (damped least squares with joint limits and a pull toward the rest pose), plus
/// DASH's distribution of side-grasp palm poses (Appendix A.2.1, Eq. 1).

#include <mujoco/mujoco.h>

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <optional>
#include <string>
#include <vector>

#include "simhuman/core/status.h"
#include "simhuman/world/sim_world.h"

namespace simhuman::control::manip {

/// The arm's 7 hinges (shoulder x, y, z, elbow, forearm rotation, wrist flexion, deviation) of
/// one side of one agent, and the bodies from the upper arm to the fingertips.
struct ArmChain {
  static constexpr int kDofs = 7;
  int agent = 0;
  bool right = true;
  int qpos[kDofs] = {}, dof[kDofs] = {}, actuator[kDofs] = {};
  double lo[kDofs] = {}, hi[kDofs] = {};  ///< joint ranges (rad)
  int palm_site = -1;                     ///< pt_<side>_palm
  int hand_body = -1;                     ///< the hand body (its frame is the hand frame)
  std::vector<int> bodies;                ///< upper arm, lower arm, hand and the hand's bodies
  std::vector<int> finger_actuators;      ///< the hand's 22 actuators (world/hand.h order)

  Eigen::VectorXd Get(const mjData* d) const;
  void Set(mjData* d, const Eigen::VectorXd& q) const;
  /// `q` clamped into the joint ranges.
  Eigen::VectorXd Clamp(const Eigen::VectorXd& q) const;
};

/// The chain of agent `agent`'s right (or left) arm; FailedPrecondition naming the agent's kind
/// when it has no dexterous hand on that side.
core::StatusOr<ArmChain> MakeArmChain(const world::SimWorld& world, int agent, bool right);

/// A wanted palm pose: the palm point (pt_<side>_palm) at `pos` and the hand frame's axes
/// (world/hand.h: x thumb side, y out of the palm, z from the fingertips to the wrist) as `rot`.
struct PalmPose {
  Eigen::Vector3d pos = Eigen::Vector3d::Zero();
  Eigen::Matrix3d rot = Eigen::Matrix3d::Identity();
  /// When set, the pose may turn as a whole about the vertical line through this point (an
  /// upright object held in the hand, whose yaw on the table does not matter): SolvePalmIk
  /// then reaches whichever turn of it the arm comes nearest.
  std::optional<Eigen::Vector3d> yaw_free_about;
};

/// Options of SolvePalmIk.
struct IkOptions {
  int max_iterations = 150;
  double damping = 0.05;       ///< DLS lambda
  double rot_weight_m = 0.15;  ///< metres of position error worth one radian of rotation
  double rest_pull = 0.02;     ///< null-space step toward the rest pose per iteration
  double tol_pos_m = 0.005, tol_rot_rad = 0.06;
};

/// The result of one IK solve.
struct IkResult {
  Eigen::VectorXd q;  ///< 7 arm angles (within ranges)
  double pos_err_m = 0, rot_err_rad = 0;
  bool converged = false;
};

/// Solves for arm angles that put the palm at `target`, starting from `q0`, with `rest` as the
/// null-space preference. `scratch` is a caller-owned mjData of the world's model holding the
/// rest of the state (the body, the objects); its arm angles are overwritten. Never fails: an
/// unreachable target gives converged = false and the closest pose found.
IkResult SolvePalmIk(const mjModel* m, mjData* scratch, const ArmChain& arm, const PalmPose& target,
                     const Eigen::VectorXd& q0, const Eigen::VectorXd& rest,
                     const IkOptions& options = {});

/// Contacts of the arm and hand with anything (the world, objects, the rest of the body) deeper
/// than `tolerance_m`, at the arm angles `q` (set into `scratch` and its kinematics run; the
/// arm's geom pairs checked by ArmCollider, arm_collision.h, which leaves scratch->contact
/// alone), ignoring contacts with the geoms of body `ignore_body` (the object in hand; -1:
/// none). Returns the number of such contacts.
int ArmContacts(const mjModel* m, mjData* scratch, const ArmChain& arm, const Eigen::VectorXd& q,
                int ignore_body = -1, double tolerance_m = 0.002);

/// DASH's side-grasp palm poses around an upright object at `centre` (its axis vertical): the
/// palm faces the axis from `standoff_m` away at height `centre.z()`, fingers horizontal, thumb
/// up, the palm point `behind_m` back from the axis along the fingers, so that the object sits
/// at the base of the fingers and they wrap around it; `yaw_rad` turns the approach about the
/// vertical (0: the palm approaches from the right-hand side, -y, with the fingers pointing +x;
/// mirrored for the left hand).
PalmPose SideGraspPose(const Eigen::Vector3d& centre, double standoff_m, double yaw_rad, bool right,
                       double behind_m = 0.035);

/// A top-grasp palm pose over a round object whose top is at `top`: the palm faces down from
/// `standoff_m` above it, the fingers point along the horizontal direction at `yaw_rad` (0: +x)
/// and the palm point sits `behind_m` back from the top along the fingers (so the object lies
/// under the base of the fingers, which wrap down around it). The same for either hand (the
/// left hand's palm faces its frame's -y; its thumb then points to the fingers' right).
PalmPose TopGraspPose(const Eigen::Vector3d& top, double standoff_m, double yaw_rad, bool right,
                      double behind_m = 0.01);

}  // namespace simhuman::control::manip
