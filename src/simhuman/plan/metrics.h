#pragma once
/// The Task Parser of UniHSI (section 3, Eq. 6-9) and its evaluation metrics (Eq. 10-11), as pure
/// functions on plain data: body points of the agents, a grounded chain and a scene catalog.
///
/// Distances are in metres and positions in the world frame (+z up, floor at z = 0).
///
/// DIRECTION CONVENTION. A pair's direction says where the joint lies relative to its contact
/// point on the part. With v_j the joint and v_np the nearest point of the part (the target),
/// the paper's distance vector is d = v_np - v_j (target minus joint); direction agreement is
///     dot = unit(v_j - v_np) . DirectionVector(direction) = -unit(d) . d_hat,
/// so "pelvis on seat surface, up" means the pelvis is above the seat, and "hand on the front of a
/// cupboard, front" means the hand is in front of it. Two cases count as full agreement
/// (dot = 1): direction kNone, and ||d|| < direction_epsilon_m (the joint is at or inside the
/// surface, where the side it lies on is ill-defined).
///
/// GET-CLOSE PAIRS (part and joint "none", e.g. {chair000, none, none, none, front}; UniHSI also
/// writes "stand up" this way). The agent must stand at the given side of the object: its pelvis,
/// projected on the floor, within get_close_radius_m of StandPoint(object, side, stand_off_m),
/// and its facing within get_close_facing_tol_rad of StandFacingYaw() (facing the object, i.e.
/// along minus the side direction). Note that "stand up" therefore also asks the agent to turn
/// and face the object it stood up from.
///
/// Thread-safety: all functions are pure; StepTracker is a plain value type (not synchronised).

#include <Eigen/Core>
#include <array>
#include <optional>
#include <vector>

#include "simhuman/core/body_joint.h"
#include "simhuman/core/geometry.h"
#include "simhuman/core/scene_catalog.h"
#include "simhuman/core/span.h"
#include "simhuman/core/status.h"
#include "simhuman/plan/contact_chain.h"

namespace simhuman::plan {

/// The 15 standard body points at the origin (a starting value for BodyPoints::pos_world).
inline std::vector<Eigen::Vector3d> ZeroBodyPoints() {
  return std::vector<Eigen::Vector3d>(core::kNumBodyJoints, Eigen::Vector3d::Zero());
}

/// Where a hand rests on its own belly, from the 15 standard body points (BodyJoint order, at
/// least 15): a point on the front of the lower trunk and the outward normal there. The pelvis
/// frame is rebuilt from points rigid in the pelvis: left/right from the hips, up from our pelvis
/// point (the sitting bones, 4 cm below the hips' middle) to the hips' middle; the point lies
/// 0.085 forward and 0.18 up from the hips' middle (the front of world/humanoid.cc's waist
/// capsule), scaled by the hips' spacing (0.17 m at scale 1).
struct BellyTouch {
  Eigen::Vector3d pos = Eigen::Vector3d::Zero();
  Eigen::Vector3d normal = Eigen::Vector3d::UnitX();
};
BellyTouch BellyPoint(core::Span<const Eigen::Vector3d> pts);

/// The body points of one agent (its catalog's, at least the 15 standard ones), and its
/// heading. One per agent, indexed by ContactPair::agent.
struct BodyPoints {
  /// Indexed by static_cast<int>(core::BodyJoint) (the agent's body-point ids).
  std::vector<Eigen::Vector3d> pos_world = ZeroBodyPoints();
  /// Unit horizontal forward direction of the pelvis (z ignored; re-normalised when used).
  Eigen::Vector3d facing_world = Eigen::Vector3d::UnitX();

  const Eigen::Vector3d& at(core::BodyJoint joint) const {
    return pos_world.at(static_cast<int>(joint));
  }
  Eigen::Vector3d& at(core::BodyJoint joint) { return pos_world.at(static_cast<int>(joint)); }
};

/// Thresholds and weights of the pair reward and success rule. Defaults follow the paper where
/// it gives numbers (0.1 m, 0.8, 0.3 m, e); the reward weights are ours.
struct PairParams {
  double contact_threshold_m = 0.1;   // Eq. 8: contact needs ||d|| < this, not contact > this
  double direction_dot_min = 0.8;     // Eq. 8: contact needs dot > this
  double direction_epsilon_m = 0.02;  // below this ||d|| the direction counts as agreeing
  double w_dis = 1.0;                 // Eq. 7 distance weight
  double w_dir = 0.5;                 // Eq. 7 direction weight (penalty for dot < 0)
  double w_dk_per_m = 5.0;            // Eq. 7 distance decay
  double not_contact_error_m = 0.3;   // Eq. 11: not-contact error is max(this - ||d||, 0)
  double get_close_radius_m = 0.3;    // pelvis (horizontal) to stand point
  /// Facing tolerance of get-close pairs. Default pi: position only, because UniHSI also
  /// writes "stand up" as a get-close pair, after which the agent faces away from the object.
  double get_close_facing_tol_rad = 3.141592653589793;
  double stand_off_m = 0.45;          // stand point distance beyond the object's bounds
  double adaptive_weight_eps = 1e-3;  // Eq. 9: e
  /// A hand's pair with its own pelvis (UniHSI's "hand on stomach", {X, pelvis, hand}) targets
  /// BellyPoint() when true (our convention), the pelvis point itself when false (UniHSI's).
  /// With this body no hand resting on the belly comes within 0.1 m of either pelvis point
  /// (docs/BENCHMARKS.md, session 23); runs report success with both (EpisodeResult).
  bool hand_on_pelvis_at_belly = true;

  /// All values finite; thresholds, weights and radii >= 0 (w_dk, epsilon of Eq. 9 > 0);
  /// direction_dot_min in [-1, 1]; facing tolerance in [0, pi]. The message names the field.
  absl::Status Validate() const;
};

/// The unit world vector of a direction for an object at `object_pose`: kUp/kDown are world
/// +z/-z; kFront/kBack/kLeft/kRight are the object's +x/-x/+y/-y turned by the object's yaw
/// (the heading of its +x axis projected on the floor), so they are always horizontal. kNone is
/// the zero vector.
Eigen::Vector3d DirectionVector(Direction d, const core::Pose& object_pose);

/// Yaw (radians, about +z from world +x) of the object's +x axis projected on the floor.
double ObjectYaw(const core::Pose& object_pose);

/// Where an agent should stand to "get close" to `object` at `side` (kFront/kBack/kLeft/kRight):
/// in the object's yaw-only frame, along the side axis at the object's LocalBounds() face on
/// that side plus `stand_off_m`, centred on the bounds across that axis; z = 0 (floor).
/// E.g. front: local (max.x + stand_off_m, (min.y + max.y) / 2, -), then turned by the yaw and
/// moved to the object's position. Aborts (SH_CHECK) for a non-side direction or an object
/// without shapes.
Eigen::Vector3d StandPoint(const core::CatalogObject& object, Direction side, double stand_off_m);

/// The yaw (radians) an agent at StandPoint(object, side, ...) has when facing the object: the
/// heading of -DirectionVector(side, object.pose).
double StandFacingYaw(const core::CatalogObject& object, Direction side);

/// The evaluation of one pair at one instant.
struct PairEval {
  /// ||d||. For get-close pairs: horizontal distance from the pelvis to the stand point.
  double distance_m = 0.0;
  /// d = v_np - v_j, target minus joint (get-close: stand point minus pelvis, z = 0).
  Eigen::Vector3d d_vec = Eigen::Vector3d::Zero();
  /// v_np: the nearest point of the part, the target body point (part_joint), or the stand point.
  Eigen::Vector3d target_world = Eigen::Vector3d::Zero();
  /// Direction agreement in [-1, 1] (see the convention above). For get-close pairs, the cosine
  /// of the angle between the agent's facing and StandFacingYaw(). 1 for not care.
  double direction_dot = 1.0;
  /// Eq. 8 (or the get-close criterion).
  bool satisfied = false;
  /// R_k of Eq. 7, clamped to [0, 1].
  double reward = 0.0;
  /// True for contact and not-contact pairs: the pairs Eq. 10 averages over.
  bool has_error = false;
  /// er_i of Eq. 11 when has_error: ||d|| for contact, max(not_contact_error_m - ||d||, 0) for
  /// not contact (the paper prints min(0.3 - ||d||, 0), which is never positive; we report how
  /// much closer than 0.3 m the joint is). 0 otherwise.
  double error_m = 0.0;
};

/// True when `pair` is a hand on its own pelvis and `params` put that touch on the belly.
bool TouchesBelly(const ContactPair& pair, const PairParams& params);

/// Evaluates one pair:
/// - target v_np: the nearest point of the part's shapes at the object's current pose
///   (core::NearestPointOnShapes; the joint itself when inside), or the body point part_joint of
///   the same agent (BellyPoint() when TouchesBelly());
/// - contact:     satisfied iff ||d|| < contact_threshold_m and dot > direction_dot_min;
///                R = clamp(w_dis exp(-w_dk ||d||) + w_dir min(dot, 0), 0, 1);
/// - not contact: satisfied iff ||d|| > contact_threshold_m; R = 1 - exp(-w_dk ||d||);
/// - not care:    satisfied, R = 1;
/// - object pair: see EvaluateObjectPair() (body points are not used);
/// - get close:   satisfied iff the pelvis (horizontal) is within get_close_radius_m of the stand
///                point and the facing is within get_close_facing_tol_rad;
///                R = clamp(w_dis exp(-w_dk dist) + w_dir min(cos(facing error), 0), 0, 1).
/// Requires a pair grounded by ValidateAndGround() against `scene` (same object ids and parts)
/// and agents.size() > pair.agent; aborts (SH_CHECK) otherwise, as that is a programming error.
PairEval EvaluatePair(const ContactPair& pair, const core::SceneCatalog& scene,
                      const std::vector<BodyPoints>& agents, const PairParams& params);

/// Evaluates an object-object pair (ContactPair::IsObjectPair(), a tabletop goal such as "the
/// red box on top of the blue cylinder"): distance ||d|| between the closest points of the
/// subject part and the object part (alternating projection; exact for convex parts);
/// direction agreement dot = unit(c - n) . DirectionVector(direction, object pose), where c is
/// the centre of the subject part and n its nearest point on the object part (so "up" means the
/// subject rests above the part), 1 for kNone or when ||c - n|| < direction_epsilon_m. Success
/// and reward as for a joint pair (contact: ||d|| < contact_threshold_m and dot >
/// direction_dot_min). Requires a grounded pair; aborts (SH_CHECK) otherwise.
PairEval EvaluateObjectPair(const ContactPair& pair, const core::SceneCatalog& scene,
                            const PairParams& params);

/// Eq. 9: w_k = (1 - R_k) / (n - sum_k R_k + eps). The weights sum to (n - sum R) / (n - sum R +
/// eps) < 1; all are 0 when every R_k is 1.
std::vector<double> AdaptiveWeights(const std::vector<double>& rewards, double eps);

/// The evaluation of one step at one instant.
struct StepEval {
  std::vector<PairEval> pairs;  // in the step's order
  std::vector<double> weights;  // w_k of Eq. 9
  double reward = 0.0;          // R^G = sum_k w_k R_k (Eq. 6)
  bool complete = false;        // every pair satisfied (Eq. 8)
};

/// A carried object is at its destination (CooHOI's rule): its origin within this of the
/// goal's horizontally, and down on the floor (its origin within kCarryGoalHeightTolM of the
/// goal's height).
inline constexpr double kCarryGoalRadiusM = 0.2;
inline constexpr double kCarryGoalHeightTolM = 0.03;
bool CarriedObjectAtGoal(const core::Pose& object, const core::Pose& goal);

/// Evaluates all pairs of `step` (see EvaluatePair) with the adaptive weights of Eq. 9. A carry
/// step with a destination (floor point, beside an object) is complete when the object is at
/// its goal (CarriedObjectAtGoal) and none of its carriers' hand pairs is satisfied (put down
/// and let go); a carry step that only holds completes on its hand pairs.
StepEval EvaluateStep(const ContactStep& step, const core::SceneCatalog& scene,
                      const std::vector<BodyPoints>& agents, const PairParams& params);

/// Settings of StepTracker.
struct TrackerParams {
  /// A step completes once EvaluateStep() reports it complete at every tick over a span of at
  /// least hold_s (from the first complete tick to the current one). 0: the first complete tick.
  double hold_s = 0.0;
  /// The plan succeeds if all n steps complete by n * budget_s_per_step (UniHSI: 10 s).
  double budget_s_per_step = 10.0;

  /// Both finite, hold_s >= 0, budget_s_per_step > 0.
  absl::Status Validate() const;
};

/// What happened to one step of a tracked plan.
struct StepRecord {
  bool completed = false;
  double completion_time_s = 0.0;  // episode time of completion, when completed
  /// True once the step's errors were recorded: at completion, or at the end of the episode
  /// (time-out or Finish()) for the step being worked on then.
  bool errors_recorded = false;
  std::vector<double> errors_m;  // er_i of its contact / not-contact pairs, in pair order
};

/// Follows a plan through an episode (the Task Parser's "fetch the next step"). Each control
/// tick, evaluate the current step with EvaluateStep() and pass it to Update(). A step completes
/// as described in TrackerParams::hold_s, then the next step becomes current. The episode ends
/// when all steps are done, when a tick comes after the time budget (n * budget_s_per_step), or
/// when Finish() is called; later Update() calls are ignored. A runner that stops at the budget
/// without a later tick (or ends early, e.g. on a fall) calls Finish().
///
/// Contact error (Eq. 10) is the mean of er_i over the contact and not-contact pairs of every
/// step whose errors were recorded: a completed step records the errors of the tick that
/// completed it; the step being worked on when the episode ends records those of its last
/// evaluation within the budget. Steps never reached record nothing.
class StepTracker {
 public:
  /// `chain` must be non-empty (validated); only its shape (steps, pairs per step) is kept.
  /// `params` must pass Validate(). Aborts otherwise.
  explicit StepTracker(const ContactChain& chain, const TrackerParams& params = {});

  /// Feeds one tick at episode time `time_s` (seconds since the episode started, non-decreasing)
  /// with `eval` = EvaluateStep() of the current step (same number of pairs; aborts otherwise).
  void Update(double time_s, const StepEval& eval);

  /// Ends the episode early (e.g. the agent fell): records the errors of the current step from
  /// its last evaluation, if any. Idempotent.
  void Finish();

  /// Index of the step being worked on; num_steps() once all are done.
  int current_step() const { return current_; }
  int num_steps() const { return static_cast<int>(records_.size()); }
  /// "Success Steps": the number of steps completed within the budget.
  int steps_completed() const { return current_; }
  /// All steps completed.
  bool done() const { return current_ == num_steps(); }
  /// A tick came after the budget before all steps were done.
  bool timed_out() const { return timed_out_; }
  /// The episode is over (done, timed out or Finish() called).
  bool finished() const { return finished_; }
  /// All steps completed within the budget.
  bool succeeded() const { return done(); }
  /// n_steps * budget_s_per_step.
  double time_budget_s() const { return budget_s_; }
  /// Per-step results, in step order.
  const std::vector<StepRecord>& records() const { return records_; }
  /// Completion times (episode seconds) of the completed steps, in order.
  std::vector<double> completion_times_s() const;
  /// Eq. 10 over the recorded errors; nullopt when no contact / not-contact error was recorded.
  std::optional<double> contact_error_m() const;
  /// Number of er_i values contact_error_m() averages over.
  int num_error_pairs() const;

 private:
  void RecordErrors(int step, const StepEval& eval);

  TrackerParams params_;
  double budget_s_;
  std::vector<int> pairs_per_step_;
  std::vector<StepRecord> records_;
  int current_ = 0;
  bool finished_ = false;
  bool timed_out_ = false;
  double last_time_s_ = 0.0;
  bool has_time_ = false;
  std::optional<double> complete_since_s_;
  std::optional<StepEval> last_eval_;  // last evaluation of the current step within the budget
};

}  // namespace simhuman::plan
