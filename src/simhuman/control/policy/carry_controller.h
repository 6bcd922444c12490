#pragma once
/// The carrying skill as a controller: LibTorch inference of a trained carry policy
/// (control/policy/carry_task.h: phases, observation, PD targets) for the carry steps of a plan
/// in which its agent carries; every other step goes to the wrapped controller. Torch stays in
/// the .cc (pimpl). Acts at 30 Hz with physics at kWalkPhysicsDt while carrying, as trained.
///
/// The carry runs the task's phases on the step's object and goal: walk to the stand point of
/// the near face, lift, carry to the goal, put down, step back. It carries boxes (one box geom);
/// other objects and steps that only hold are refused with an error that ends the episode.

#include <memory>
#include <string>

#include "simhuman/control/controller.h"
#include "simhuman/control/policy/carry_task.h"

namespace simhuman::control {

class CarryPolicyController : public Controller {
 public:
  /// Loads a carry policy file for agent `agent` of `world` (both must outlive the controller;
  /// so must `other`, which runs the steps without a carry for this agent). Errors name the
  /// file; a policy of another task is InvalidArgument.
  static core::StatusOr<std::unique_ptr<CarryPolicyController>> Load(const std::string& path,
                                                                     const world::SimWorld* world,
                                                                     int agent, Controller* other);
  ~CarryPolicyController() override;

  std::string name() const override;
  absl::Status Act(const Observation& obs) override;
  void Targets(double time_s, core::Span<double> ctrl) const override;
  double control_period_s() const override;
  double physics_timestep_s() const override;

  /// Whether the last Act() ran a carry (and its state).
  bool carrying() const;
  const CarryState& state() const;

  struct Impl;

 private:
  explicit CarryPolicyController(std::unique_ptr<Impl> impl);
  std::unique_ptr<Impl> impl_;
};

}  // namespace simhuman::control
