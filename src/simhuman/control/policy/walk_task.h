#pragma once
/// The walking skill's task definition, shared by training (learn/walk_env) and deployment
/// (control/policy/PolicyController), so both build the same observations, commands and PD
/// targets. Torch-free. See docs/FORMATS.md ("Walking policy") for the spaces.
///
/// Timing: physics at kWalkPhysicsDt (120 Hz), policy at 30 Hz (kWalkSubsteps physics steps
/// per action). The runner switches the model's timestep to kWalkPhysicsDt while the walking
/// policy is in control.
///
/// Frames: the heading frame is the world frame rotated by the pelvis yaw (x forward, z up).
/// Thread-safety: pure functions; WalkState is a plain value (one per agent / env).

#include <mujoco/mujoco.h>

#include <Eigen/Core>
#include <array>
#include <string>
#include <string_view>
#include <vector>

#include "simhuman/world/humanoid.h"
#include "simhuman/world/sim_world.h"

namespace simhuman::control {

inline constexpr double kWalkPhysicsDt = 1.0 / 120.0;  ///< s
inline constexpr int kWalkSubsteps = 4;                ///< physics steps per policy step
inline constexpr double kWalkPolicyDt = kWalkPhysicsDt * kWalkSubsteps;  ///< s (30 Hz)
inline constexpr int kWalkObsDim = 116;
inline constexpr int kWalkActDim = world::kHumanoidDofs;
/// The walking observation's layout (WalkObservation): height, up and forward axes, linear and
/// angular velocity (13 entries), then kWalkActDim each of the hinge angles minus the nominal
/// pose, the hinge velocities and the previous action, then the command part.
inline constexpr int kWalkObsHinges = 13;
inline constexpr int kWalkObsHingeVel = kWalkObsHinges + kWalkActDim;
inline constexpr int kWalkObsPrevAction = kWalkObsHingeVel + kWalkActDim;
inline constexpr double kWalkActionScale = 0.5;  ///< rad of PD-target offset per action unit
inline constexpr double kWalkActionClip = 3.0;   ///< actions are clipped to +-this

/// Gait and command parameters (defaults are what the shipped policy was trained with).
struct WalkParams {
  double vmax_mps = 1.0;         ///< commanded speed far from the target
  double gait_period_s = 0.9;    ///< one full left+right cycle
  double swing_frac = 0.42;      ///< fraction of the cycle a foot is in the air (~0.38 s)
  double start_radius_m = 0.25;  ///< start stepping when farther than this from the target
  double stop_radius_m = 0.12;   ///< stop stepping when closer than this ...
  double start_yaw_rad = 0.35;   ///< ... or when the heading error exceeds this (start)
  double stop_yaw_rad = 0.14;    ///< ... and is below this (stop)
  double max_yaw_rate = 1.5;     ///< rad/s
  /// A walk to a target farther than far_m faces the direction of travel (turns, then walks
  /// forward); closer than near_m it keeps the requested heading; in between it blends the two.
  double near_m = 0.5;
  double far_m = 1.2;
  /// Farther than this, a target behind slows the walk until the human has turned toward it.
  double turn_first_m = 1.0;
  /// A walk that starts closer than this to its target is a short step: it keeps the requested
  /// heading all the way (steps back or sideways, as people do for a metre or so) unless the
  /// target ends up 0.5 m beyond that. 0: every walk follows the near/far blend.
  double short_step_m = 1.5;
  // the reference gait's shape (rad, at full stepping amplitude)
  double hip_swing_rad = 0.30;   ///< sagittal hip excursion each way at vmax
  double knee_swing_rad = 0.9;   ///< swing-phase knee flexion (peak added to the nominal)
  double knee_stance_rad = 0.1;  ///< stance-phase knee flexion (peak added to the nominal)
  double knee_bend_rad = 0.0;    ///< added to the nominal knee while stepping (-: straighter)
};

/// The named gaits. A walking policy file records the gait it was trained with
/// (PolicyMeta::variant) and runs with it: "" is the original (0.9 s cycle, 1.0 m/s, knees
/// bent 14-20 degrees), "human" is shaped after adult gait norms (1.05 s cycle = 114 steps/min,
/// 1.3 m/s, longer steps, straighter stance legs; docs/BENCHMARKS.md, issue 21).
core::StatusOr<WalkParams> WalkGait(std::string_view name);
/// The valid gait names ("" first).
std::vector<std::string> WalkGaitNames();

/// The command derived from the target each policy step (heading frame, the adult's units:
/// physical speeds are these times sqrt(s), WalkScale).
struct WalkCommand {
  double vx = 0, vy = 0;  ///< m/s
  double yaw_rate = 0;    ///< rad/s
};

/// Task state of one walking agent.
struct WalkState {
  Eigen::Vector2d target_xy = Eigen::Vector2d::Zero();  ///< world frame, m
  double target_yaw_rad = 0;                            ///< heading to stop with
  double phase = 0;                                     ///< gait clock in [0, 1)
  double amplitude = 0;                                 ///< smoothed stepping amplitude in [0, 1]
  bool stepping = false;                                ///< hysteresis state: walking or standing
  bool short_step = false;  ///< this walk started within short_step_m (WalkParams)
  WalkCommand cmd;
  double facing_rad = 0;  ///< heading the command turns toward (bearing far, target yaw near)
  std::array<float, kWalkActDim> prev_action{};
};

/// Geometry indices the task reads (resolved once per model).
struct WalkIndex {
  world::AgentIndex agent;
  int floor_geom = -1;
  int left_foot_geom = -1, right_foot_geom = -1;
  std::array<double, kWalkActDim> ctrl_lo{}, ctrl_hi{};
};

/// Froude scaling of a body of length scale s (world::AgentIndex::scale): a child of scale 0.6
/// walks like the adult with every length times s and every time times sqrt(s) (the servo gains
/// scale with s^4 and the masses with s^3, world/humanoid.h). The task works in the adult's
/// units: WalkState's command and clock, WalkParams and the observation are all in them, so one
/// policy serves every size and an adult (s = 1) sees exactly what it always saw.
struct WalkScale {
  double length = 1.0;  ///< s
  double time = 1.0;    ///< sqrt(s)
};
/// The agent's scale factors.
WalkScale WalkScaleOf(const WalkIndex& ix);

/// Resolves indices for agent `a` of `world`. Errors name a missing geom.
core::StatusOr<WalkIndex> MakeWalkIndex(const world::SimWorld& world, int a);

/// The nominal standing pose (28 hinge angles, actuator order), knees slightly bent.
const std::array<double, kWalkActDim>& WalkNominalPose();

/// The reference gait: 28 joint targets at gait `phase` for stepping `amplitude` and `cmd`.
void WalkReference(const WalkParams& p, double phase, double amplitude, const WalkCommand& cmd,
                   double* q28);

/// Which feet the reference expects on the ground (+1), in the air (-1) or either (0).
void WalkExpectedContacts(const WalkParams& p, double phase, double amplitude, int* left,
                          int* right);

/// Pelvis position and heading (yaw) of the agent.
void PelvisPose(const mjData* d, const WalkIndex& ix, Eigen::Vector3d* pos, double* yaw);

/// Distance to the target (m, horizontal) and heading error (target yaw minus pelvis yaw,
/// wrapped to [-pi, pi]).
void WalkErrors(const mjData* d, const WalkIndex& ix, const WalkState& s, double* dist_m,
                double* yaw_err_rad);

/// Updates the command, the stepping hysteresis, the amplitude and advances the clock by one
/// policy step. Call once per policy step before WalkObservation.
void UpdateWalkCommand(const WalkParams& p, const mjData* d, const WalkIndex& ix, WalkState* s);

/// Foot contact flags (any contact of the foot geom).
void FootContacts(const mjData* d, const WalkIndex& ix, bool* left, bool* right);

/// Writes kWalkObsDim floats (raw, unnormalized) to `obs`.
void WalkObservation(const WalkParams& p, const mjData* d, const WalkIndex& ix, const WalkState& s,
                     float* obs);

/// PD targets from a raw action: reference gait + kWalkActionScale * clip(action), clipped
/// to the actuator ranges. The arms (shoulders and elbows) follow the reference alone, hanging
/// and swinging against the legs; the policy's 8 arm outputs are ignored (policies that
/// steered them held an arm out for balance, docs/BENCHMARKS.md, session 6).
void WalkTargets(const WalkParams& p, const WalkIndex& ix, const WalkState& s, const float* action,
                 double* ctrl28);

/// Height (m, world z) of the lowest corner of the box geoms `geoms` (the feet) in `d`'s
/// current kinematics: subtract it from the root height to stand them on the floor.
double LowestBoxCornerZ(const mjModel* m, const mjData* d, const std::vector<int>& geoms);

/// Whether WalkTargets uses action entry `j` (false for the 8 arm entries it ignores).
bool WalkActionUsed(int j);

}  // namespace simhuman::control
