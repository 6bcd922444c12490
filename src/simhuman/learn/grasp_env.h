#pragma once
/// DASH's grasping stage as a training task (Appendix A.3): a human seated at a table (pelvis
/// held), right arm and dexterous hand, an object of DASH's ranges (box, cylinder or sphere,
/// width 6-10 cm, height 13-18 cm, 1-5 kg, friction 0.8-1.2) on the table in front of it. Each
/// episode starts where the reaching stage ends: the palm beside the object, facing it from a
/// side-grasp pose drawn from DASH's distribution (Eq. 1) and solved by IK, the hand open; the
/// object is placed within 2 cm of where the plan thought it was (vision noise).
///
/// Observations and actions are control/manip/grasp_task.h's (the pipeline runs the same code).
/// Reward (DASH Eq. 4-7, x 0.1): 10 r_o (the object's horizontal drift) + r_p (fingertips and
/// palm near the object; the thumb x 5) + 2 r_c (touching phalanges; the thumb's x 5) + 1.5 r_s
/// (the four fingers in similar poses) + r_d (the drop test: for the last 0.4 s the table stops
/// colliding and a downward force of half the object's weight pulls it; -15 per step while it
/// is out of the hand). Success: the object still in the hand at the end of the drop test.
///
/// Each env owns a copy of the model: the object's shape, size, mass and friction change per
/// episode, and the drop test switches the table's collisions off.
///
/// The residual variant ("grasp-residual") learns a correction on top of the scripted grasp
/// (control/manip/scripted_grasp.h): the targets move by the scripted action plus
/// kGraspResidualScale times the policy's, so training starts from the scripted grasp's skill.

#include <memory>
#include <vector>

#include "simhuman/control/manip/grasp_task.h"
#include "simhuman/control/manip/tabletop_pipeline.h"
#include "simhuman/core/rng.h"
#include "simhuman/learn/vec_env.h"
#include "simhuman/world/sim_world.h"

namespace simhuman::learn {

/// One sampled grasp problem (for tests and evaluation).
struct GraspProblem {
  control::manip::GraspShape shape = control::manip::GraspShape::kCylinder;
  double width_m = 0.08, height_m = 0.15, mass_kg = 2.0, friction = 1.0;
  Eigen::Vector3d planned_pos = Eigen::Vector3d::Zero();  ///< base centre the plan believes
  Eigen::Vector3d actual_pos = Eigen::Vector3d::Zero();   ///< where it really stands
};

class GraspTask : public VecTask {
 public:
  /// `residual`: the policy's action is added to the scripted grasp's (the "grasp-residual" task).
  static core::StatusOr<std::unique_ptr<GraspTask>> Create(int num_envs, bool residual = false);
  ~GraspTask() override;
  std::string name() const override { return residual_ ? "grasp-residual" : "grasp"; }
  int num_envs() const override { return static_cast<int>(envs_.size()); }
  int obs_dim() const override { return control::manip::kGraspObsDim; }
  int act_dim() const override { return control::manip::kGraspActDim; }
  double action_limit() const override { return 1.0; }
  void Reset(int i, uint64_t seed, float* obs) override;
  void Step(int i, const float* action, float* obs, StepInfo* info) override;

  static constexpr int kSubsteps = 6;     ///< 240 Hz physics, 40 Hz policy (DASH: k = 6)
  static constexpr int kGraspSteps = 60;  ///< 1.5 s to grasp
  static constexpr int kDropSteps = 16;   ///< 0.4 s drop test
  static constexpr int kMaxSteps = kGraspSteps + kDropSteps;

  const mjModel* model(int i) const { return envs_[i].m; }
  const mjData* data(int i) const { return envs_[i].d; }
  const GraspProblem& problem(int i) const { return envs_[i].problem; }
  const control::manip::GraspIndex& index() const { return ix_; }
  /// Whether env i's object is out of the hand (distance or height).
  bool Dropped(int i) const;

 private:
  struct Env {
    mjModel* m = nullptr;
    mjData* d = nullptr;
    mjData* scratch = nullptr;
    control::manip::GraspState s;
    GraspProblem problem;
    control::manip::GraspPolicyFn scripted;  ///< the residual task's base action
    int steps = 0;
    bool dropped_in_test = false;
  };
  GraspTask() = default;
  void Shape(Env& e) const;                     // writes the problem's object into the env's model
  bool PlaceArm(Env& e, core::Rng& rng) const;  // IK to a side-grasp start; false if none
  control::manip::TabletopGoal Goal(const Env& e) const;  // the problem as the pipeline's goal
  double Reward(Env& e, bool drop_test);
  void SetTableCollisions(Env& e, bool on) const;

  bool residual_ = false;
  std::unique_ptr<world::SimWorld> world_;
  control::manip::GraspIndex ix_;
  std::vector<Env> envs_;
  std::vector<double> seated_qpos_, seated_ctrl_;
  int object_body_ = -1, object_qpos_ = -1, object_dof_ = -1;
  int object_geom_[3] = {-1, -1, -1};  // box, cylinder, sphere
  std::vector<int> rim_geoms_;         // the cylinder's rest rings (world/model_builder.h)
  std::vector<int> table_geoms_;
  double table_top_z_ = 0;
};

}  // namespace simhuman::learn
