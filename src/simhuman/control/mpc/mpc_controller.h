#pragma once
/// Reference-guided predictive sampling MPC (training-free default controller).
///
/// Each control period: shift the nominal spline of servo targets, draw `samples` candidates
/// (the shifted nominal, the pure reference, and Gaussian perturbations around the nominal),
/// roll each out on a planning copy of the model (one mjData per thread), score them with the
/// step's contact terms (adaptive weights, UniHSI Eq. 9), reference tracking, balance,
/// uprightness, effort and smoothness, and keep the cheapest. The reference is a smooth ramp
/// from the pose at the start of the step to a pose solved from the step's contacts
/// (reference_pose.h). Rollout noise derives from (seed, replan index, rollout index), so the
/// result is the same with 1 or 2 threads.

#include <array>
#include <memory>
#include <optional>
#include <vector>

#include "simhuman/control/controller.h"
#include "simhuman/control/mpc/mpc_config.h"
#include "simhuman/control/mpc/reference_pose.h"

namespace simhuman::control {

class MpcController : public Controller {
 public:
  /// `world` must outlive the controller. Validates `config`.
  static absl::StatusOr<std::unique_ptr<MpcController>> Create(const world::SimWorld* world,
                                                               int agent, const MpcConfig& config,
                                                               uint64_t seed);
  ~MpcController() override;

  std::string name() const override { return "mpc-" + config_.preset; }
  absl::Status Act(const Observation& obs) override;
  void Targets(double time_s, core::Span<double> ctrl) const override;
  double control_period_s() const override { return config_.replan_s; }

  /// The reference pose solved for the current step (diagnostics, tests).
  const ReferencePose& reference() const { return goal_; }
  /// True while the fall monitor has switched to the recovery objective.
  bool recovering() const { return recovering_; }
  /// Cost of the chosen candidate at the last replan.
  double last_cost() const { return last_cost_; }
  /// Replans done, and replans skipped because the caller was behind real time.
  long replans() const { return iteration_; }
  long skipped_replans() const { return skipped_replans_; }

 private:
  using Knots = std::vector<std::array<double, world::kHumanoidDofs>>;
  MpcController() = default;
  void StartStep(const Observation& obs, const StepTask& task);
  /// Moves the reference's hand targets past their contact points by the steady miss.
  void CorrectAim(const Observation& obs);
  /// Updates the hand servo's arm offsets from the current hand misses
  /// (MpcConfig::hand_servo_gain).
  void ServoHands(const Observation& obs);
  /// Servo targets `knot` plus the hand servo's offsets, within the actuator ranges.
  void WithServo(const double* knot, double* out) const;
  ReferencePose RefPose(double t) const;
  std::array<double, world::kHumanoidDofs> RefHinges(double t) const;
  double SegmentSeconds(const ReferencePose& a, const ReferencePose& b) const;
  void SetReference(double now, const std::vector<ReferencePose>& keys, const mjData* d);
  void RefPoints(double t, std::array<Eigen::Vector3d, core::kNumBodyJoints>* pts) const;
  double Rollout(int thread, const Knots& knots, double t0, const mjData* start) const;
  static void Interp(const Knots& knots, double t0, double span, double t, double* out);

  const world::SimWorld* world_ = nullptr;
  int agent_ = 0;
  MpcConfig config_;
  uint64_t seed_ = 1;
  mjModel* plan_model_ = nullptr;
  std::vector<mjData*> thread_data_;
  mjData* scratch_ = nullptr;

  // current step
  int step_index_ = -1;
  StepTask task_;
  std::vector<double> term_weights_;
  std::vector<ReferencePose> keys_;  // reference keyframes: current pose, ..., goal
  std::vector<double> key_s_;        // their times after ramp_t0_
  ReferencePose goal_;
  double ramp_t0_ = 0, ramp_s_ = 1;
  std::vector<std::array<Eigen::Vector3d, core::kNumBodyJoints>> ref_table_;  // every 20 ms
  double seat_top_z_ = -1;
  double stand_balance_from_s_ =
      1e9;  // after ramp_t0_; see StartStep  // seat height for sit postures (balance gating)
  bool recovering_ = false;
  /// The stand-up step being worked on while the human first sits up on a bed's edge.
  std::optional<StepTask> get_up_;
  bool rise_from_seat_ = false;  // the next StartStep rises from a seat whatever its height
  bool sit_up_again_ = false;    // the next StartStep sits up on the bed's edge again
  double next_aim_s_ = 0;        // next aim correction (see MpcConfig::aim_gain)
  std::array<double, world::kHumanoidDofs> servo_{};  // hand servo offsets on servo targets
  std::array<std::array<int, 4>, 2> arm_dofs_{};      // hinge indices: right, left arm
  std::array<bool, 2> servo_active_{};                // right, left hand held by the servo
  double progress_floor_ = 0;  // 1 once the goal has been reached and is only being refined

  // plan
  Knots nominal_;
  double nominal_t0_ = 0;
  bool reference_changed_ = true;  // since the last replan (a skipped replan must not miss it)
  long skipped_replans_ = 0;
  long iteration_ = 0;
  double last_cost_ = 0;
  std::array<double, world::kHumanoidDofs> lo_{}, hi_{}, noise_scale_{};
};

}  // namespace simhuman::control
