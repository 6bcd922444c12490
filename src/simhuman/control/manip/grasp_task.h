#pragma once
/// The grasp stage as a policy sees it (DASH, Appendix A.3): observations, actions and the
/// servo targets they drive, shared by the training environment (learn/grasp_env.h) and the
/// tabletop pipeline, so a trained policy deploys unchanged. Torch-free.
///
/// Observation (kGraspObsDim floats): the arm's 7 and the hand's 22 joint angles, the arm's 7
/// joint velocities (x 0.1), the previous targets of all 29 (as angles), binary touch of the 17
/// hand parts (world/hand.h HandTouchParts()) with the grasped object, the task location (the
/// object's planned position, relative to the shoulder point, metres) and the object's shape
/// one-hot (box, cylinder, sphere). DASH leaves finger velocities out; so do we.
/// Action (kGraspActDim floats in [-1, 1]): changes of the 29 targets per policy step, scaled by
/// kArmStepRad and kFingerStepRad; targets stay within the joint ranges. The arm's servos get a
/// gravity and Coriolis feed-forward (ctrl = target + bias / kp), the fingers plain targets.

#include <mujoco/mujoco.h>

#include <Eigen/Core>
#include <array>
#include <string>
#include <vector>

#include "simhuman/control/manip/arm_ik.h"
#include "simhuman/core/status.h"
#include "simhuman/world/hand.h"
#include "simhuman/world/sim_world.h"

namespace simhuman::control::manip {

inline constexpr int kGraspDofs = ArmChain::kDofs + world::kHandFingerDofs;  // 29
inline constexpr int kGraspActDim = kGraspDofs;
inline constexpr int kGraspTouchParts = 17;
inline constexpr int kGraspObsDim =
    kGraspDofs + ArmChain::kDofs + kGraspDofs + kGraspTouchParts + 3 + 3;  // 88
inline constexpr double kArmStepRad = 0.04;     ///< largest arm target change per policy step
inline constexpr double kFingerStepRad = 0.12;  ///< largest finger target change per step

/// A residual grasp policy's action is scaled by this before it is added to the scripted
/// grasp's (scripted_grasp.h; the "grasp-residual" training task).
inline constexpr double kGraspResidualScale = 0.5;

/// out = base + kGraspResidualScale * residual, clipped to [-1, 1] (kGraspActDim floats each).
void AddGraspResidual(const float* base, const float* residual, float* out);

/// Shapes the policy is told about (the one-hot).
enum class GraspShape { kBox = 0, kCylinder = 1, kSphere = 2 };

/// Model addresses of one arm and hand, and of its touch parts and fingertips.
struct GraspIndex {
  ArmChain arm;
  std::array<int, kGraspDofs> qpos{}, actuator{};
  std::array<double, kGraspDofs> lo{}, hi{};
  std::vector<int> touch_of_geom;  ///< per model geom: touch part index or -1
  std::array<int, 5> tip_site{};   ///< thumb, index, middle, ring, little tips
  int shoulder_site = -1;          ///< the shoulder body point of that side
};

/// The index of agent `agent`'s right (or left) dexterous arm; errors as MakeArmChain.
core::StatusOr<GraspIndex> MakeGraspIndex(const world::SimWorld& world, int agent, bool right);

/// What the grasp stage remembers between policy steps.
struct GraspState {
  std::array<double, kGraspDofs> target{};             ///< current servo targets (rad)
  Eigen::Vector3d task_pos = Eigen::Vector3d::Zero();  ///< where the object was planned to be
  GraspShape shape = GraspShape::kBox;
  int object_body = -1;
};

/// Sets the hand's 22 joints in `d` to the open pre-shape the reach carries (DASH holds one
/// designed pose while reaching): fingers straight, the thumb extended and abducted out of the
/// palm's way. Only qpos; run kinematics after.
void SetOpenHand(const GraspIndex& ix, mjData* d);

/// Sets the hand's 22 joints in `d` to the pre-shape of a top grasp of a round object (a claw):
/// fingers spread and a little curled, the thumb opened across from them, so that the hand can
/// come down over the object and close around it below its widest part. Only qpos.
void SetClawHand(const GraspIndex& ix, mjData* d);

/// Targets equal to the current joint angles (the start of a stage).
void HoldCurrentPose(const mjData* d, const GraspIndex& ix, GraspState* s);

/// Touch flags (0 or 1) of the 17 hand parts against `object_body`'s geoms, into `out`.
void GraspTouch(const mjModel* m, const mjData* d, const GraspIndex& ix, int object_body,
                float* out);

/// Writes the observation (kGraspObsDim floats).
void GraspObservation(const mjModel* m, const mjData* d, const GraspIndex& ix, const GraspState& s,
                      float* obs);

/// Moves the targets by `action` (clipped to [-1, 1], scaled, kept within the ranges).
void ApplyGraspAction(const GraspIndex& ix, const float* action, GraspState* s);

/// Writes the arm's and hand's servo controls for the current targets into d->ctrl (call every
/// physics step: the arm's feed-forward uses the current bias forces).
void WriteGraspCtrl(const mjModel* m, mjData* d, const GraspIndex& ix, const GraspState& s);

}  // namespace simhuman::control::manip
