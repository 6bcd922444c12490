#pragma once
/// The single-carrier carrying skill's task definition, shared by training (learn/carry_env) and
/// deployment, as walk_task.h is for walking: phases, reference poses, observations and PD
/// targets. Torch-free.
///
/// A carry runs in phases. The walking part (legs, trunk, command, gait clock) is the walking
/// skill's (walk_task.h): its observation is the first kWalkObsDim entries of the carry
/// observation, so a walking policy initialises a carry policy with its input layer widened.
///  - kApproach: walk to the stand point in front of the box's near face, facing the box.
///  - kLift: squat with the arms open around the box, press the hands on its two side faces,
///    rise to the holding pose (kLiftSeconds, driven by a clock).
///  - kCarry: walk to the carry stand point (destination minus the holding offset), the arms
///    keep pressing on the box.
///  - kPutDown: squat holding the box, open the arms, rise (kPutDownSeconds).
///  - kRetreat: step back from the box, arms hanging; the walking reference alone.
///
/// Frames: the stand frame has its origin on the floor at the stand point, +x toward the box.
/// Box "held points" are the centres of its two side faces (left: +y of the stand frame).

#include <mujoco/mujoco.h>

#include <Eigen/Core>
#include <array>

#include "simhuman/control/policy/walk_task.h"
#include "simhuman/world/sim_world.h"

namespace simhuman::control {

inline constexpr int kCarryExtraObsDim = 64;
inline constexpr int kCarryObsDim = kWalkObsDim + kCarryExtraObsDim;
inline constexpr int kCarryActDim = kWalkActDim;
inline constexpr double kLiftSeconds = 3.2;
inline constexpr double kPutDownSeconds = 3.2;

enum class CarryPhase : int { kApproach, kLift, kCarry, kPutDown, kRetreat };
inline constexpr int kNumCarryPhases = 5;
const char* CarryPhaseName(CarryPhase p);

/// Geometry of the skill (defaults are what the shipped policy trains with).
struct CarryParams {
  double stand_gap_m = 0.20;  ///< stand point to the box's near face (pelvis over the feet)
  /// pelvis to the held box's near face while carrying, and the held box centre above the
  /// pelvis: at the chest, close in, where the swinging thighs do not reach it (0.16 m and
  /// 0.02 m until session 46: the box hung at the hips and the knees kicked it round)
  double hold_gap_m = 0.08;
  double hold_rise_m = 0.20;
  /// the holding pose leans the trunk back by this much per kilogram held (rad/kg), the arms
  /// and box with it, so the load's weight stays over the feet (docs/BENCHMARKS.md, issue 17,
  /// session 46)
  double hold_lean_rad_per_kg = 0.02;
  /// hands outside the side faces before squeezing. 0.12 brings them down beside the box, not
  /// on its top edges, and with squat_hinge_rad 0.8 the model-based lift (zero action, quasi-
  /// static support) lifts 38 of 96 boxes instead of 23; the policies trained so far learned on
  /// 0.02 and 0, and fall with the new keyframes, so these stay the defaults until a policy is
  /// trained on them (docs/BENCHMARKS.md, issue 17, session 47; carry probe --open, --hinge)
  double open_m = 0.02;
  /// hip flexion beyond the knees' in the lifting squat (rad): > 0 a stoop-squat, the hips back
  /// and the trunk over the box, so the shallowest squat whose hands reach is higher (0: a deep
  /// squat, trunk upright, that tends to sit back and fall; see open_m)
  double squat_hinge_rad = 0.0;
  double squeeze_m = 0.04;         ///< hand targets inside the side faces (the press)
  double grasp_frac = 0.80;        ///< grasp height as a fraction of the box height
  double arrive_radius_m = 0.2;    ///< at a stand point: within this ...
  double arrive_yaw_rad = 0.2;     ///< ... and heading error below this ...
  double arrive_speed_mps = 0.25;  ///< ... and slower than this
  /// ... or within arrive_radius_m of it for this long in the phase (summed), whatever the
  /// speed and heading: the lift and the put-down cannot be avoided by hovering near the stand
  /// point (a policy that fell in the squats learned to; docs/BENCHMARKS.md, issue 17, session 26)
  double arrive_dwell_s = 1.0;
  /// the put-down also starts once the held box's centre is this close (horizontally) to the
  /// destination, wherever the pelvis is: a carrier holding the box just over the destination
  /// with its pelvis outside arrive_radius_m could dodge it (issue 17, session 26)
  double put_down_box_radius_m = 0.15;
  double retreat_m = 0.6;  ///< step back this far after putting down
  /// the approach aims this far past the stand point (arrival is judged at the stand point):
  /// the walker stops about 0.3 m short of its target
  double approach_lead_m = 0.30;
  /// held points lie at most this far behind the box's near face (deep boxes are held near
  /// their near end, against the body, as people hold them)
  double max_reach_depth_m = 0.30;
  /// Grip servo (while the hands should be on the box): each policy step adds this fraction of
  /// the arm joint change that would bring each hand `squeeze_m` inside its held face to an
  /// offset on that arm's targets (integral action: the hand closes on the face wherever the
  /// squat has put the body, and presses harder the longer the face blocks it). 0 disables it.
  double grip_gain = 0.3;
  double grip_max_rad = 0.5;   ///< largest offset on one arm joint
  double grip_reach_m = 0.25;  ///< the servo acts on a hand within this of its target
  /// The walking reference gait (WalkGait) of the walking policy the carry policy starts from:
  /// the approach, the carry and the retreat walk to it
  WalkParams walk;
  /// The carry phase's top walking speed (m/s): the command and the reference stride use
  /// min(walk.vmax_mps, this) while carrying (a walker holding 5-7 kg keeps it 6 of 6 times at
  /// 0.8 against 1 of 6 at the human gait's 1.3; docs/BENCHMARKS.md, issue 17, session 26)
  double carry_vmax_mps = 0.8;
};

/// The box being carried, in the world (from the simulation or a perception estimate).
struct CarryBox {
  Eigen::Vector3d pos = Eigen::Vector3d::Zero();  ///< centre, m
  Eigen::Matrix3d rot = Eigen::Matrix3d::Identity();
  Eigen::Vector3d half = Eigen::Vector3d::Constant(0.25);  ///< half extents, m
  Eigen::Vector3d linvel = Eigen::Vector3d::Zero(), angvel = Eigen::Vector3d::Zero();
  double mass_kg = 5;
  int geom = -1;  ///< the box's geom in the model (-1: not simulated, e.g. an estimate)
};

/// Joint-space keyframes of one carry (28 hinges, actuator order), solved for a box size.
struct CarryPoses {
  std::array<double, kWalkActDim> squat_open{};     ///< squatting, hands beside the faces
  std::array<double, kWalkActDim> squat_squeeze{};  ///< squatting, hands pressing
  std::array<double, kWalkActDim> hold{};           ///< standing, box held in front
  double squat_pelvis_z = 0.9;                      ///< pelvis height of the squat, m
  double squat_pitch_rad = 0;  ///< forward pitch of the pelvis that balances the squat
  double ik_error_m = 0;       ///< worst hand distance to its keyframe point (diagnostic)
  double hold_lean_rad = 0;    ///< the carry's lean back from `hold` (LiftGeometry::hold_lean_rad)
};

/// Task state of one carrying agent.
struct CarryState {
  CarryPhase phase = CarryPhase::kApproach;
  double phase_time_s = 0;
  double near_stand_s = 0;  ///< time within arrive_radius_m of the stand point in this phase
  WalkState walk;           ///< the walking part (its target is the current stand point)
  WalkParams gait;  ///< the walking reference gait (CarryParams::walk, copied by BeginCarry)
  Eigen::Vector2d dest_xy = Eigen::Vector2d::Zero();    ///< where the box goes (centre), m
  Eigen::Vector2d face_dir = Eigen::Vector2d::UnitX();  ///< stand frame +x at pick-up (world)
  Eigen::Vector2d stand_xy = Eigen::Vector2d::Zero();   ///< stand point of the current phase
  Eigen::Vector3d half_stand = Eigen::Vector3d::Constant(0.25);  ///< box half extents, stand frame
  /// the left held point in the box frame (the right one mirrors its side component)
  Eigen::Vector3d held_left_local = Eigen::Vector3d::Zero();
  int held_axis = 1;  ///< box axis (0 x, 1 y) normal to the held faces
  CarryPoses poses;
  std::array<double, kWalkActDim> grip{};  ///< grip servo offsets on the arm targets, rad
  /// the approach walks the line that ends at the stand point (else it heads for that line)
  bool approach_on_line = false;
};

/// Indices the task reads: the walking ones plus the hand sites.
struct CarryIndex {
  WalkIndex walk;
  int left_hand_site = -1, right_hand_site = -1;
  int left_hand_geom = -1, right_hand_geom = -1;
  /// the hands' grip actuators (world::HumanoidSpec::grip_n; -1: a humanoid without grip)
  int left_grip = -1, right_grip = -1;
};

core::StatusOr<CarryIndex> MakeCarryIndex(const world::SimWorld& world, int a);

/// Where the hands go, in the stand frame at lift time (origin on the floor between the feet,
/// +x the pelvis heading): the held points and their faces' outward normals, and the box's
/// extents in the carrier's frame (for the holding pose).
struct LiftGeometry {
  Eigen::Vector3d left = Eigen::Vector3d::Zero(), right = Eigen::Vector3d::Zero();
  Eigen::Vector3d left_out = Eigen::Vector3d::UnitY(), right_out = -Eigen::Vector3d::UnitY();
  double half_x = 0.25, half_y = 0.25;  ///< box half extents along and across the heading
  double held_dx = 0, held_dz = 0;      ///< held points' offset from the box centre
  double hold_lean_rad = 0;  ///< the holding trunk's lean back (CarryParams::hold_lean_rad_per_kg)
};

/// Solves the keyframes with a balanced squat (centre of mass over the feet) and a small
/// Gauss-Newton IK of the arms on `scratch` (any mjData of the model; overwritten).
CarryPoses SolveCarryPoses(const CarryParams& p, const mjModel* m, mjData* scratch,
                           const CarryIndex& ix, const LiftGeometry& g);

/// The lift geometry of the current state: the human where it stands, the box where it lies.
LiftGeometry MakeLiftGeometry(const CarryParams& p, const mjData* d, const CarryIndex& ix,
                              const CarryState& s, const CarryBox& box);

/// Chooses the face of `box` nearest to `from_xy`: the stand point before it and the stand
/// direction (+x toward the box), and the box half extents in that stand frame.
void ChooseStandFace(const CarryParams& p, const CarryBox& box, const Eigen::Vector2d& from_xy,
                     Eigen::Vector2d* stand_xy, Eigen::Vector2d* face_dir,
                     Eigen::Vector3d* half_in_stand);

/// Starts a carry: phase kApproach toward the chosen face, the held points fixed on the box.
void BeginCarry(const CarryParams& p, const CarryIndex& ix, const mjData* d, const CarryBox& box,
                const Eigen::Vector2d& dest_xy, CarryState* s);

/// Enters the lift from where the human stands (what arriving at the stand point does): solves
/// the keyframes on `scratch`. Also starts episodes at the box in training.
void StartLift(const CarryParams& p, const mjModel* m, mjData* scratch, const mjData* d,
               const CarryIndex& ix, const CarryBox& box, CarryState* s);

/// Reference-state initialisation inside a started lift (training): sets the phase time to
/// `t_s` (clamped to the squat-and-squeeze part, before the rise), the hinges and controls to
/// the reference there, the root pitched as the squat keyframe scaled by the squat depth, the
/// feet flat where they were and the lowest foot corner on the floor, at rest.
void PoseInLift(const mjModel* m, mjData* d, const CarryIndex& ix, double t_s, CarryState* s);

/// Seconds into the lift at which the rise starts (the end of PoseInLift's range).
double LiftRiseStartSeconds();

/// Enters the put-down where the human stands (what arriving at the carry stand point does):
/// the walking target is held there and the gait's full speed restored.
void StartPutDown(const CarryParams& p, const mjData* d, const CarryIndex& ix, CarryState* s);

/// Reference-state initialisation inside a started put-down (training): sets the phase time to
/// `t_s` (clamped to the lowering part, [0, PutDownLowerEndSeconds()]), the hinges and controls
/// to the put-down reference there computed with the keyframes `pose_with` (e.g. solved with no
/// press, so the hands touch the held faces instead of starting inside the box), the root
/// pitched as the squat keyframe scaled by the progress down, the feet flat where they were and
/// the lowest foot corner on the floor, the human at rest. The box is not moved.
void PoseInPutDown(const mjModel* m, mjData* d, const CarryIndex& ix, double t_s,
                   const CarryPoses& pose_with, CarryState* s);

/// Seconds into the put-down at which the squat is down (the end of PoseInPutDown's range).
double PutDownLowerEndSeconds();

/// Advances phases, the walking command and the grip servo by one policy step (call before
/// CarryObservation). Entering the lift solves its keyframes (SolveCarryPoses) on `scratch`.
/// `d` must hold the kinematics of its pose (as mj_step leaves them).
void UpdateCarry(const CarryParams& p, const mjModel* m, mjData* scratch, const mjData* d,
                 const CarryIndex& ix, const CarryBox& box, CarryState* s);

/// Writes kCarryObsDim floats: the walking observation, then the box, the destination, the
/// phase and the hands (see docs/FORMATS.md, "Carrying policy"). While the task holds the arms
/// (CarryArmsHeld) the walking part's arm entries are blind (CarryBlindArms).
void CarryObservation(const mjData* d, const CarryIndex& ix, const CarryState& s,
                      const CarryBox& box, float* obs);

/// Whether the task, not the walking gait, poses the arms: the lift, the carry and the put-down.
bool CarryArmsHeld(const CarryState& s);

/// "Blind arms": overwrites the 8 arm entries (those WalkActionUsed ignores) of a walking
/// observation `walk_obs` (kWalkObsDim floats) with what a walker sees of its own arms while it
/// walks: the angles of the gait's arm swing at the current clock and command, velocity 0 and
/// previous action 0. A walking policy shown the holding arms falls even with a 0.5 kg box; shown
/// its own swing it carries boxes up to 7 kg (docs/BENCHMARKS.md, issue 17, session 26). The
/// hands stay observed through the carry entries (hands relative to the held points, contacts).
void CarryBlindArms(const CarryState& s, float* walk_obs);

/// The phase's reference pose (28 hinges): walking gait, lift or put-down blend, holding arms.
void CarryReference(const CarryState& s, double* q28);

/// PD targets: reference + grip + kWalkActionScale * clip(action), clipped to the actuator
/// ranges.
void CarryTargets(const CarryIndex& ix, const CarryState& s, const float* action, double* ctrl28);

/// Whether the phase expects the hands on the box (the squeeze part of lift and put-down and
/// the whole carry).
bool CarryHandsOnBox(const CarryState& s);

/// Sets the hands' grip controls (if the humanoid has them): on while the hands hold the box.
void SetCarryGrip(const CarryIndex& ix, const CarryState& s, mjData* d);

/// The held points (world): on the box's two held faces at the grasp height, fixed in the box
/// frame at BeginCarry.
void CarryHeldPoints(const CarryState& s, const CarryBox& box, Eigen::Vector3d* left,
                     Eigen::Vector3d* right);

/// Reads the box state from its (single box) geom on a free body.
CarryBox ReadCarryBox(const mjModel* m, const mjData* d, int geom);

/// Height of the box's lowest corner, m.
double BoxLowestZ(const CarryBox& box);

/// Whether each hand geom touches the box geom.
void HandBoxContacts(const mjData* d, const CarryIndex& ix, const CarryBox& box, bool* left,
                     bool* right);

}  // namespace simhuman::control
