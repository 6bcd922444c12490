#pragma once
/// A training-free controller for the carrying skill's hard part (issue 17): predictive sampling
/// over the carry task's residual action (the same action a carry policy outputs, on top of the
/// phase's reference and the grip servo). Every control step it shifts the best action spline
/// of the last step, draws candidates around it, rolls each out on its own mjData of the carry
/// model (the box included, so the rollouts feel its mass and friction) with the task's own
/// phase update, and keeps the cheapest. The cost asks for balance (the capture point over the
/// feet), the reference posture, the hands on the held points, the box rising once the rise
/// begins and staying level, and no fall. Torch-free; deterministic for a seed.

#include <mujoco/mujoco.h>

#include <array>
#include <vector>

#include "simhuman/control/policy/carry_task.h"
#include "simhuman/core/rng.h"

namespace simhuman::control {

struct CarryMpcOptions {
  int samples = 24;         ///< candidates per control step (the shifted best and zero included)
  double horizon_s = 0.5;   ///< rollout length
  int knots = 3;            ///< spline knots over the horizon (piecewise linear)
  double sigma = 0.35;      ///< exploration noise, action units
  double w_track = 2.0;     ///< hinge angles to the reference (rad^2)
  double w_balance = 40.0;  ///< capture point to the feet's middle (m, smooth L1)
  double w_hands = 30.0;    ///< hands to their held points while the phase holds (m)
  double w_box = 60.0;      ///< box below its wanted height once the rise has begun (m)
  double w_tilt = 10.0;     ///< box tilt (1 - cos)
  double w_upright = 10.0;  ///< trunk tilt (1 - cos of pelvis-to-head with vertical)
  double w_fall = 200.0;    ///< head below 0.9 m or pelvis below the squat
  double w_action = 0.02;   ///< action size
  double w_feet = 100.0;    ///< feet sliding or stepping from where the lift began (m)
  uint64_t seed = 1;
};

class CarryMpc {
 public:
  /// `m` must outlive the controller (the carry env's model, box shaped).
  CarryMpc(const mjModel* m, const CarryIndex& ix, const CarryParams& p, int box_geom,
           const CarryMpcOptions& o);
  ~CarryMpc();
  CarryMpc(const CarryMpc&) = delete;
  CarryMpc& operator=(const CarryMpc&) = delete;

  /// Chooses the action (kCarryActDim floats) for the control step that starts in `d` with the
  /// task state `s`.
  void Act(const mjData* d, const CarryState& s, float* action);

  double last_cost() const { return last_cost_; }
  /// The chosen candidate's rollout: box lowest corner at the horizon (diagnostic).
  double last_box_low() const { return last_box_low_; }

 private:
  using Knots = std::vector<std::array<float, kCarryActDim>>;
  double Rollout(const mjData* start, const CarryState& s0, const Knots& k, double* box_low);
  void ActionAt(const Knots& k, int step, int steps, float* a) const;

  const mjModel* m_;
  CarryIndex ix_;
  CarryParams p_;
  int box_geom_;
  CarryMpcOptions o_;
  mjData* d_ = nullptr;
  mjData* scratch_ = nullptr;
  Knots best_;
  std::array<Eigen::Vector2d, 2> feet0_;  ///< feet (left, right) where the lift began
  bool have_feet0_ = false;
  core::Rng rng_;
  long iteration_ = 0;
  double last_cost_ = 0, last_box_low_ = 0;
};

}  // namespace simhuman::control
