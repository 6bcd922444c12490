#pragma once
/// The walking task for training: the runner's humanoid (world::SimWorld of an empty scene,
/// physics at control::kWalkPhysicsDt) walks to a target stand point and stops there facing a
/// target heading. Observations, commands and PD targets come from control/policy/walk_task.h,
/// so the trained policy runs unchanged in the PolicyController.
///
/// Bodies of several sizes (`body_scales`) train one policy: the task works in the adult's
/// units (control::WalkScale), and the thresholds below are the adult's, times the scale.
///
/// Episodes: 20 s; a fall (pelvis < 0.55 m, head < 0.8 m, torso tilted > 70 deg, or any body
/// part other than the feet touching the floor) terminates. After holding the target for 1.5 s
/// a new target is drawn from the current pose. Targets: 0.3-10 m away (skewed short), at a
/// bearing within +-A of the current heading and a final heading within +-A of the bearing,
/// where A grows from 45 to 180 deg with the curriculum level.

#include <memory>
#include <vector>

#include "simhuman/control/policy/route_steer.h"
#include "simhuman/control/policy/walk_task.h"
#include "simhuman/core/rng.h"
#include "simhuman/learn/vec_env.h"
#include "simhuman/world/sim_world.h"

namespace simhuman::learn {

/// Reward weights of the walking task (the sum is scaled by `scale`).
struct WalkRewardWeights {
  double velocity = 1.0, progress = 1.5, yaw_rate = 0.5, facing = 0.5, gait_legs = 1.0,
         gait_upper = 0.3, contact = 0.3, upright = 0.5, height = 0.3, alive = 0.5, at_target = 1.0;
  /// the leg term is exp(-sum of squared leg errors to the reference / this), rad^2
  double gait_legs_width = 0.5;
  /// head and trunk held upright, as a person walks (1/e at about 20 degrees of tilt each)
  double posture = 1.0;
  double action_rate = 0.02, power = 2e-5, foot_slip = 0.5;
  double scale = 0.1;
};

/// Terms of the last reward (for logs and tests).
struct WalkRewardTerms {
  double velocity = 0, progress = 0, yaw_rate = 0, facing = 0, gait_legs = 0, gait_upper = 0,
         contact = 0, upright = 0, height = 0, posture = 0, at_target = 0, action_rate = 0,
         power = 0, foot_slip = 0, total = 0;
};

/// MuJoCo constraint solver of the training physics. Newton is what the runner uses; PGS
/// solves the same contact problem (dual form, fewer iterations to a looser fit) and steps the
/// walking human about 1.4x faster (docs/BENCHMARKS.md).
enum class WalkPhysicsSolver { kNewton, kPgs };

class WalkTask : public VecTask {
 public:
  /// Builds one model per body scale and `num_envs` mjData, env i holding a human of
  /// `body_scales[i % size]`, walking to the reference `gait` (control::WalkGait), rewarded
  /// with `weights`. Errors from model building, scales outside [0.5, 1.5] and unknown gaits.
  static core::StatusOr<std::unique_ptr<WalkTask>> Create(
      int num_envs, WalkPhysicsSolver solver = WalkPhysicsSolver::kNewton,
      const std::vector<double>& body_scales = {1.0}, const std::string& gait = "",
      const WalkRewardWeights& weights = {});
  ~WalkTask() override;

  std::string name() const override { return "walk"; }
  int num_envs() const override { return static_cast<int>(envs_.size()); }
  int obs_dim() const override { return control::kWalkObsDim; }
  int act_dim() const override { return control::kWalkActDim; }
  /// The arm entries are unused: the arms follow the reference (control::WalkTargets).
  bool action_used(int j) const override { return control::WalkActionUsed(j); }
  double action_limit() const override { return control::kWalkActionClip; }
  void Reset(int i, uint64_t seed, float* obs) override;
  void Step(int i, const float* action, float* obs, StepInfo* info) override;
  double curriculum() const override { return curriculum_; }
  void set_curriculum(double c) override { curriculum_ = c; }
  /// AMP features (learn/amp_features.h) at the policy rate; AmpFeatures runs mj_kinematics on
  /// env i first (physics steps leave positions one step behind qpos).
  int amp_feature_dim() const override;
  void AmpFeatures(int i, float* out) override;
  core::StatusOr<std::vector<float>> AmpClipFeatures(const MotionClip& clip) const override;

  /// The model of env 0 (every env's, with one body scale).
  const mjModel* model() const { return worlds_[0]->model(); }
  /// Env i's human's length scale.
  double body_scale(int i) const { return worlds_[envs_[i].w]->agent(0).scale; }
  const mjData* data(int i) const { return envs_[i].d; }
  const control::WalkState& state(int i) const { return envs_[i].s; }
  const WalkRewardTerms& last_terms(int i) const { return envs_[i].terms; }
  /// Places env i's target (world frame) for tests and evaluation.
  void SetTarget(int i, double x, double y, double yaw_rad);
  /// Whether env i has fallen (the termination test).
  bool Fallen(int i) const;
  /// Share of new targets that end a random route of 2-3 legs (turns up to 125 degrees), walked
  /// as the walking controller walks routes in scenes (control/policy/route_steer.h: a carrot
  /// ahead, turns on the spot, the final heading near the goal); 0: every target is straight.
  void set_route_share(double share) { route_share_ = share; }
  /// Whether env i is on a route (tests).
  bool on_route(int i) const { return !envs_[i].route.empty(); }

  static constexpr int kMaxSteps = 600;  ///< 20 s at 30 Hz

 private:
  struct Env {
    mjData* d = nullptr;
    int w = 0;  // which world (body scale)
    control::WalkState s;
    core::Rng rng{0};
    int steps = 0, hold = 0;
    bool success = false;
    WalkRewardTerms terms;
    // a route to the target (empty: straight at it)
    control::RouteFollower route;
    control::RouteSteer steer;
    Eigen::Vector2d goal = Eigen::Vector2d::Zero();
    double goal_yaw = 0;
    bool route_final = false;
  };
  WalkTask() = default;
  void DrawTarget(Env& e);
  // a route of random legs from where env e stands; its target is steered along it
  void DrawRoute(Env& e, const Eigen::Vector2d& from, double yaw);
  // the policy's target this step: the route's carrot, turn or goal (no route: unchanged)
  void SteerRoute(Env& e);
  std::vector<std::unique_ptr<world::SimWorld>> worlds_;  // one per body scale
  std::vector<control::WalkIndex> ixs_;                   // per world
  control::WalkParams params_;
  WalkRewardWeights w_;
  std::vector<Env> envs_;
  std::vector<char> foot_body_;  // per body id: 1 for feet
  double curriculum_ = 0;
  double route_share_ = 0;
};

using control::LowestBoxCornerZ;  // (control/policy/walk_task.h)

}  // namespace simhuman::learn
