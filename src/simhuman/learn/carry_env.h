#pragma once
/// The single-carrier carrying task for training (CooHOI's single-agent skill): a human walks
/// to a box on the floor, lifts it with both hands pressed on two side faces, carries it to a
/// destination on the floor, puts it down and steps back. Phases, references, observations and
/// PD targets come from control/policy/carry_task.h, so the trained policy deploys unchanged.
///
/// Each env owns a copy of the model so the box's size and mass differ per episode. Boxes are
/// cubes of side 0.4-0.6 m and 2-5 kg at curriculum 0, growing to CooHOI's 0.25-0.75 m and
/// 2-13 kg at 1; the human starts 1-2 m (up to 5 m) from the box, the destination is 1-3 m (up
/// to 10 m) from it in any direction. A configured share start part-way into the put-down (none
/// by default), a share of the others (35 % by default) holding the box, in the carry phase, and
/// half the rest at the box, lifting (as DeepMimic's reference state initialisation starts
/// episodes inside the hard part of a motion).
///
/// Terminations: a fall (a body other than the feet and hands on the floor, the pelvis or the
/// head too low for the phase), a kick (the box sliding faster than 1 m/s while no hand should
/// hold it), a drop (the box back on the floor during the carry phase) and losing the box (its
/// centre more than 1.2 m from the pelvis while held) and stalling (still approaching after 20 s,
/// or still carrying after 15 s: without it a policy learns to stop short of its stand points
/// and never squat; the squats also start after 1 s near them, CarryParams::arrive_dwell_s;
/// training only: evaluation ends at its own time limit).
/// Success: the box at rest on the floor within 0.2 m of the destination after the put-down, the
/// human standing.
///
/// Stages train parts of the carry as skills of their own, chained at deployment with a walking
/// policy for the approach and the retreat (docs/BENCHMARKS.md, issue 17, session 46):
///  - the lift (task "carry-lift", CarryStage::kLift): every episode starts at the box (a share
///    posed part-way into the squat) and ends when the lift does, a success if the box is handed
///    over held (LiftHandedOver), a failure ("not lifted") if not;
///  - the delivery (task "carry-deliver", CarryStage::kDeliver): every episode starts holding the
///    box and ends when the put-down does, a success if the box rests on the floor within 0.2 m of
///    the destination and the human stands (Delivered), a failure ("not put down") if not.

#include <memory>
#include <vector>

#include "simhuman/control/policy/carry_task.h"
#include "simhuman/core/rng.h"
#include "simhuman/learn/vec_env.h"
#include "simhuman/world/sim_world.h"

namespace simhuman::learn {

/// Reward terms of the last step (for logs and tests).
struct CarryRewardTerms {
  double walk = 0, pose = 0, hands = 0, lifted = 0, to_dest = 0, placed = 0, posture = 0,
         action_rate = 0, power = 0, total = 0;
};

/// Why a carry episode ended early (or kNone).
enum class CarryFailure {
  kNone,
  kFall,
  kKick,
  kDrop,
  kLost,
  kStalled,
  kNotLifted,
  kNotPlaced,
  kNonFinite
};
const char* CarryFailureName(CarryFailure f);

/// Which part of the carry an episode trains: all of it, the lift, or the carry and put-down.
enum class CarryStage { kAll, kLift, kDeliver };
/// The training task's name of a stage: "carry", "carry-lift", "carry-deliver".
const char* CarryStageTask(CarryStage stage);

/// Whether the lift hands the box over to the carry held: the box's bottom at least 0.3 m up
/// and within 30 degrees of level, both hands touching it, the pelvis above 0.8 m and the trunk
/// within 30 degrees of upright.
bool LiftHandedOver(const mjData* d, const control::CarryIndex& ix, const control::CarryBox& box);

/// Whether the put-down has delivered the box: resting on the floor (lowest corner under 3 cm,
/// slower than 0.1 m/s) within 0.2 m of `dest_xy`, the pelvis above 0.8 m.
bool Delivered(const mjData* d, const control::CarryIndex& ix, const control::CarryBox& box,
               const Eigen::Vector2d& dest_xy);

class CarryTask : public VecTask {
 public:
  /// `gait`: the walking reference gait (control::WalkGait name) of the walking policy the
  /// carry policy starts from. `grip`: the human's hands grip what they touch (the
  /// "humanoid_grip" kind, world::HumanoidSpec::grip_n) while they hold the box.
  /// `stage`: the whole carry, or a part of it (CarryStageTask names the task).
  static core::StatusOr<std::unique_ptr<CarryTask>> Create(int num_envs, std::string_view gait = "",
                                                           bool grip = false,
                                                           CarryStage stage = CarryStage::kAll);
  ~CarryTask() override;

  std::string name() const override { return CarryStageTask(stage_); }
  CarryStage stage() const { return stage_; }
  int num_envs() const override { return static_cast<int>(envs_.size()); }
  int obs_dim() const override { return control::kCarryObsDim; }
  int act_dim() const override { return control::kCarryActDim; }
  void Reset(int i, uint64_t seed, float* obs) override;
  void Step(int i, const float* action, float* obs, StepInfo* info) override;
  double action_limit() const override { return control::kWalkActionClip; }
  double curriculum() const override { return curriculum_; }
  void set_curriculum(double c) override { curriculum_ = c; }

  const mjModel* model(int i) const { return envs_[i].m; }
  const mjData* data(int i) const { return envs_[i].d; }
  const control::CarryState& state(int i) const { return envs_[i].s; }
  const CarryRewardTerms& last_terms(int i) const { return envs_[i].terms; }
  CarryFailure last_failure(int i) const { return envs_[i].failure; }
  int box_geom() const { return box_geom_; }
  /// The skill's geometry and servos (probes and tests may change them before Reset).
  control::CarryParams& params() { return params_; }
  const control::CarryIndex& index() const { return ix_; }
  /// Sets env i's box (cube side, mass), placement and destination, and restarts the carry
  /// (tests and evaluation). The human keeps its pose.
  void SetBox(int i, double side_m, double mass_kg, const Eigen::Vector3d& pos, double yaw_rad,
              const Eigen::Vector2d& dest_xy, float* obs);

  static constexpr int kMaxSteps = 1200;  ///< 40 s at 30 Hz (training episodes)

  /// Starts env i's lift now from where the human stands (tests and probes; the box must be in
  /// front of it, e.g. placed by SetBox).
  /// `pose_at_s` >= 0 poses the human inside the lift at that time (PoseInLift).
  void StartLiftNow(int i, float* obs, double pose_at_s = -1);

  /// Starts env i holding its box (reference-state initialisation of the carry phase; tests,
  /// probes): after StartLiftNow's keyframes are solved, the human stands upright in the holding
  /// keyframe where it is, the box is moved so that its held points lie between the hands with
  /// `squeeze_m` of press, and the lift's clock is at its end, so the next step enters the carry.
  void StartHoldingNow(int i, float* obs);

  /// Starts env i holding its box `t_s` seconds into the put-down (reference-state
  /// initialisation of the squat down; tests, probes): StartHoldingNow's keyframes with the
  /// hands touching the held faces, the human posed by control::PoseInPutDown (t_s clamped to
  /// [0, control::PutDownLowerEndSeconds()]), the box between the hands (raised if it would be
  /// in the floor), and the destination moved to the box's place, so that a put-down from here
  /// succeeds.
  void StartPutDownNow(int i, double t_s, float* obs);

  /// The default share of training Reset()s that start holding the box (StartHoldingNow).
  static constexpr double kDefaultHeldStartFraction = 0.35;
  /// Sets that share, in [0, 1] (the training config's carry_held_start_frac, validated there;
  /// out of range is a bug). Evaluation never starts holding.
  void set_held_start_fraction(double f);
  double held_start_fraction() const { return held_start_fraction_; }

  /// The default share of training Reset()s that start inside the put-down (StartPutDownNow,
  /// uniformly over its lowering part); the held share applies to the other resets.
  static constexpr double kDefaultPutDownStartFraction = 0.0;
  /// Sets that share, in [0, 1] (the training config's carry_put_down_start_frac, validated
  /// there; out of range is a bug). Evaluation never starts inside the put-down.
  void set_put_down_start_fraction(double f);
  double put_down_start_fraction() const { return put_down_start_fraction_; }

  /// Quasi-static support in the squats (control/policy/carry_support.h): while lifting and
  /// putting down, the servo targets carry the torques that hold the pose on the feet, and the
  /// ankles keep the centre of mass over them (a model-based lift; off by default, the probe's
  /// --support 1; docs/BENCHMARKS.md, issue 17, session 39).
  void set_squat_support(bool on) { squat_support_ = on; }
  bool squat_support() const { return squat_support_; }

  /// Evaluation starts: no episode starts holding the box, at the box or inside the lift (Reset
  /// always walks up from 1-2 m, up to 5 m at curriculum 1), and episodes are cut after `max_steps`
  /// policy steps.
  void SetEvaluation(int max_steps) {
    evaluation_ = true;
    max_steps_ = max_steps;
  }

 private:
  struct Env {
    mjModel* m = nullptr;  // this env's copy (box size and mass)
    mjData* d = nullptr;
    mjData* scratch = nullptr;  // for the keyframe IK
    control::CarryState s;
    core::Rng rng{0};
    int steps = 0, done_hold = 0;
    bool success = false;
    CarryFailure failure = CarryFailure::kNone;
    CarryRewardTerms terms;
  };
  CarryTask() = default;
  void ShapeBox(Env& e, double side_m, double mass_kg) const;
  void StartHeld(int i, double put_down_at_s, float* obs);  // put_down_at_s < 0: carry phase
  CarryFailure Check(const Env& e, const control::CarryBox& box) const;
  double Reward(Env& e, const control::CarryBox& box, const float* action, double power);
  std::unique_ptr<world::SimWorld> world_;
  control::CarryIndex ix_;
  control::CarryParams params_;
  std::vector<Env> envs_;
  std::vector<char> allowed_floor_;  // per body id: feet and hands may touch the floor
  int box_geom_ = -1, box_body_ = -1, box_qpos_ = -1;
  double curriculum_ = 0;
  bool evaluation_ = false;
  bool squat_support_ = false;
  CarryStage stage_ = CarryStage::kAll;
  int max_steps_ = kMaxSteps;
  double held_start_fraction_ = kDefaultHeldStartFraction;
  double put_down_start_fraction_ = kDefaultPutDownStartFraction;
};

}  // namespace simhuman::learn
