#pragma once
/// DASH's transition stages for one arm (Appendix A.2): a final arm pose from a distribution of
/// palm poses (parameterised IK, collision-free, wrist nearest its rest), a collision-free
/// joint path (RRTConnect, shortcut), the last 10 % reshaped so the palm arrives along the
/// approach direction, retimed to a bell-shaped speed profile with a terminal palm speed, and
/// tracked through the arm's servos with inverse dynamics (Eq. 2 plus feed-forward and a
/// clamped integral). Used for reaching (empty hand) and transport (an object in the hand).

#include <mujoco/mujoco.h>

#include <Eigen/Core>
#include <string>
#include <vector>

#include "simhuman/control/manip/arm_ik.h"
#include "simhuman/control/manip/retime.h"
#include "simhuman/control/manip/rrt_planner.h"
#include "simhuman/control/manip/tracker.h"
#include "simhuman/core/status.h"

namespace simhuman::control::manip {

/// The arm planner's defaults: a budget of 20,000 validity checks (about 2 s of full-model
/// collision checks on the seated humanoid), so that a plan's outcome does not depend on the
/// machine's load, with a 10 s wall-clock backstop.
inline PlannerOptions ArmPlannerDefaults() {
  PlannerOptions p;
  p.max_validity_checks = 20000;
  p.time_limit_s = 10;
  return p;
}

/// Settings of PlanArmMotion.
struct ArmMotionOptions {
  PlannerOptions planner = ArmPlannerDefaults();  ///< RRTConnect budget, seed, shortcutting
  double terminal_palm_speed_mps = 0.4;  ///< DASH: the palm still moves at 0.4 m/s on arrival
  double mean_path_speed = 1.2;          ///< rad/s of joint-space arc length (sets the duration)
  double max_joint_speed = 3.0;          ///< rad/s per joint
  double reshape_fraction = 0.1;         ///< the final part of the path given the approach tangent
  double contact_tolerance_m = 0.002;    ///< penetration a pose may have and still be free
  /// The arm keeps this far from movable objects (free bodies) other than `approach_body`, so
  /// that the tracked arm, which strays a little from its path, does not knock them over; when
  /// no pose or path keeps it, the plan only avoids touching them (ArmMotion::clearance_kept)
  double object_clearance_m = 0.02;
  int approach_body = -1;  ///< the object reached for (-1: none): it may come closer
  IkOptions ik;            ///< the goal poses' inverse kinematics
  int ik_restarts = 8;     ///< further IK seeds per goal when no goal is free from the current arm
  /// The arm angles the goals' IK starts from and prefers (empty: the current arm's). A hand
  /// raised before the reach (PlanArmThrough) keeps the arm poses a reach from the hanging
  /// arm would end in, so the hand meets the object as it would have.
  Eigen::VectorXd ik_from;
  /// Bodies whose contacts with the arm do not count (the object in the hand during transport).
  std::vector<int> ignore_bodies;
  /// The object in the hand (transport; -1: none): it moves with the hand, its pose relative to
  /// the hand kept from the start, and its contacts with anything but the arm and hand (another
  /// object it would knock over, the table) make a pose invalid as the arm's own do.
  int carried_body = -1;
  /// The carried object's origin stays at least this high (world z, m): it goes over the table,
  /// not round below its edge
  double carried_min_z = -1e9;
};

/// A planned arm motion.
struct ArmMotion {
  Trajectory trajectory;    ///< arm angles over time, from the current pose
  int goal_index = -1;      ///< which palm pose it reaches
  Eigen::VectorXd goal_q;   ///< the arm angles there
  int goals_reachable = 0;  ///< palm poses with a collision-free IK solution
  double plan_time_s = 0;   ///< IK, search, shortcut and retiming
  /// The path keeps ArmMotionOptions::object_clearance_m from movable objects; false when no
  /// pose or path did and the plan only avoids touching them
  bool clearance_kept = true;
};

/// Plans the arm of `arm` from its pose in `d` to one of `goals` (palm poses, e.g.
/// SideGraspPose() over theta). `approach_dirs` (world, one per goal, or empty) is the palm's
/// direction of travel on arrival at that goal (empty or zero: keep the path's own). `scratch` is a
/// caller-owned mjData of the model (its state is overwritten). Errors name the stage:
/// FailedPrecondition "plan failure: no collision-free arm pose for any of N palm poses (U out of
/// the arm's reach, C in collision)", NotFound
/// "plan failure: no collision-free path ..." (the planner's message), InvalidArgument for bad
/// options.
core::StatusOr<ArmMotion> PlanArmMotion(const mjModel* m, const mjData* d, mjData* scratch,
                                        const ArmChain& arm, const std::vector<PalmPose>& goals,
                                        const std::vector<Eigen::Vector3d>& approach_dirs,
                                        const ArmMotionOptions& options = {});

/// Plans the arm of `arm` from its pose in `d` through the arm angles `vias` in turn, straight
/// in joint space from each to the next, ending at rest at the last (PlanArmMotion's collision
/// rules and clearance). A seated person lifts a hand hanging beside the thigh over the table's
/// edge with the elbow drawn back; a path searched straight for the object swings the arm out
/// round the edge instead. Errors: FailedPrecondition "plan failure: via N is in collision",
/// NotFound "plan failure: no straight path to via N", InvalidArgument for bad options or a via
/// of the wrong size.
core::StatusOr<ArmMotion> PlanArmThrough(const mjModel* m, const mjData* d, mjData* scratch,
                                         const ArmChain& arm,
                                         const std::vector<Eigen::VectorXd>& vias,
                                         const ArmMotionOptions& options = {});

/// Settings of PlanArmAlong.
struct ArmAlongOptions {
  /// No joint moves further than this between two neighbouring palm poses (more: a flip of
  /// the IK)
  double max_step_rad = 0.3;
  /// The poses before the last may turn this far from theirs (when more than ArmMotionOptions'
  /// ik tolerance: a held object may tilt on the way)
  double via_tol_rot_rad = 0;
  /// Arm angles the posture moves toward along the way (empty: none): each pose's IK prefers
  /// the blend of the start's angles and these at its place along the path, so that the arm
  /// ends near them rather than wherever the poses' IK drifts (a shoulder raised to its limit)
  Eigen::VectorXd rest_to;
};

/// Plans the arm from its pose in `d` along `palm_path` (palm poses close together, e.g. every
/// 2 cm): each solved by IK from the arm angles of the one before, straight in joint space
/// between them, ending at rest at the last; PlanArmMotion's collision rules, clearance and
/// carried object. A hand that carries something up, across and down on a line a person's
/// would take, where a joint-space search may swing it round the body. Errors: InvalidArgument
/// for an empty path, bad options or rest_to of the wrong size; FailedPrecondition "plan
/// failure: palm pose K of N is out of the arm's reach", "... is in collision", "... makes a
/// joint jump by X rad"; NotFound "plan failure: no straight path to palm pose K of N".
core::StatusOr<ArmMotion> PlanArmAlong(const mjModel* m, const mjData* d, mjData* scratch,
                                       const ArmChain& arm, const std::vector<PalmPose>& palm_path,
                                       const ArmMotionOptions& options = {},
                                       const ArmAlongOptions& along = {});

/// The last part of `path` from where the palm (`arm`'s palm site) is `palm_m` in a straight
/// line from where it ends (the path searched back from its end every `step_rad` of arc
/// length), the body otherwise as in `d`; the whole path when the palm is nowhere that far.
/// `scratch` is overwritten.
JointPath PathTail(const mjModel* m, const mjData* d, mjData* scratch, const ArmChain& arm,
                   const JointPath& path, double palm_m, double step_rad = 0.01);

/// Plans the arm from its pose in `d` to the start of `tail` (the last part of a path planned
/// from elsewhere, e.g. PathTail of a reach planned from the hanging arm), searched as
/// PlanArmMotion's, then along `tail` to its end; retimed as one path, arriving with the
/// terminal palm speed of `options`. A hand raised in front of the shoulder then arrives as the
/// reach from the hanging arm would have. As PlanArmMotion, when no path keeps
/// `options.object_clearance_m` it plans one that only avoids touching (clearance_kept false).
/// Errors: InvalidArgument for an empty tail or bad options, FailedPrecondition "plan failure: the
/// tail is in collision", NotFound "plan failure: no collision-free path ..." (the planner's
/// message).
core::StatusOr<ArmMotion> PlanArmOnto(const mjModel* m, const mjData* d, mjData* scratch,
                                      const ArmChain& arm, const JointPath& tail,
                                      const ArmMotionOptions& options = {});

/// Tracks an arm trajectory through the arm's position servos: each physics step, the desired
/// acceleration (JointTracker: feed-forward plus PID) becomes joint torques by inverse dynamics,
/// and the servos are given the targets that produce those torques (ctrl = q + tau / kp; the
/// servos' force limits bound them, as muscles are bounded). Not thread-safe.
class ArmTracker {
 public:
  static core::StatusOr<ArmTracker> Create(const mjModel* m, const ArmChain& arm,
                                           const TrackerGains& gains = {});
  /// Writes the arm's controls for time `t_s` along `traj` (clamped to its end: holding the
  /// last pose) into d->ctrl; `d` must hold the current state after a forward pass.
  void Control(const Trajectory& traj, double t_s, mjData* d);
  /// Holds `q` (the arm's angles) still.
  void Hold(const Eigen::VectorXd& q, mjData* d);
  void Reset() { tracker_.Reset(); }

 private:
  ArmTracker(const mjModel* m, const ArmChain& arm, JointTracker tracker, InverseDynamics id)
      : m_(m), arm_(arm), tracker_(std::move(tracker)), id_(std::move(id)) {}
  void Drive(const Eigen::VectorXd& q_ref, const Eigen::VectorXd& qd_ref,
             const Eigen::VectorXd& qdd_ref, mjData* d);
  const mjModel* m_;
  ArmChain arm_;
  JointTracker tracker_;
  InverseDynamics id_;
};

}  // namespace simhuman::control::manip
