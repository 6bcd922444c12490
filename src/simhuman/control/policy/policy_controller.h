#pragma once
/// The walking skill as a controller: LibTorch inference of a trained walking policy
/// (control/policy/walk_task.h spaces) that walks to the stand point of a get-close step and
/// stops there facing the object. Torch stays inside the .cc (pimpl).
///
/// Timing: acts at 30 Hz and asks the runner to step physics at kWalkPhysicsDt (the rate it
/// was trained at) through physics_timestep_s().

#include <memory>
#include <string>

#include "simhuman/control/controller.h"
#include "simhuman/control/navigation.h"
#include "simhuman/control/policy/route_steer.h"
#include "simhuman/control/policy/walk_task.h"

namespace simhuman::control {

/// Arrival tolerances the controller reports (and the `walk` suite checks).
struct WalkTolerance {
  double radius_m = 0.2;
  double yaw_rad = 15.0 * M_PI / 180.0;
  double speed_mps = 0.2;  ///< "stopped": pelvis horizontal speed below this
};

class WalkPolicyController : public Controller {
 public:
  /// Loads a policy file (or a training checkpoint) for agent `agent` of `world` (which must
  /// outlive the controller). Errors name the file; a policy of another task or with other
  /// dimensions is InvalidArgument.
  static core::StatusOr<std::unique_ptr<WalkPolicyController>> Load(const std::string& path,
                                                                    const world::SimWorld* world,
                                                                    int agent);
  ~WalkPolicyController() override;

  std::string name() const override { return "walk-policy"; }
  /// Takes the target from obs.task (stand point and facing of a get-close step) unless a
  /// fixed target was set, then infers the PD targets (deterministic: the Gaussian's mean).
  absl::Status Act(const Observation& obs) override;
  void Targets(double time_s, core::Span<double> ctrl) const override;
  double control_period_s() const override { return kWalkPolicyDt; }
  double physics_timestep_s() const override { return kWalkPhysicsDt; }

  /// Fixes the target (world frame), overriding the step's stand point (evaluation).
  void SetTarget(double x, double y, double yaw_rad);
  /// True when the agent stands within `tol` of the target, stopped and no longer stepping.
  bool Arrived(const mjData* d, const WalkTolerance& tol = {}) const;
  const WalkState& state() const;
  /// Forgets the gait state and the route (call when taking over from another controller).
  void Restart();
  /// With navigation on (the default), a get-close step is walked along an obstacle-avoiding
  /// route over the scene catalog (control/navigation.h): the policy steers to a point
  /// kRouteLookaheadM ahead on the route and to the stand point itself for the last stretch.
  /// Off: straight at the stand point.
  void set_navigation(bool on);
  /// The route being followed (nullptr when none).
  const NavPath* route() const;
  // the route's carrot, the turn on the spot and the final turn: route_steer.h
  static constexpr double kReplanOffRouteM = 0.8;
  /// A route that starts with less than kExitRoomM of room (PointClearance: stood up between a
  /// chair and a table) begins with a short step, heading kept (sideways or back), to its first
  /// point with that room, searched every kExitProbeM within kMaxExitM; the step ends within
  /// kExitDoneM of it.
  static constexpr double kExitRoomM = 0.25;
  /// The same with less than kTurnRoomM of room when the route's way kTurnProbeM ahead is more
  /// than kTurnFirstRad from the walker's heading (it would turn on the spot first).
  static constexpr double kTurnRoomM = 0.45;
  static constexpr double kTurnProbeM = 0.4;
  static constexpr double kExitProbeM = 0.05;
  static constexpr double kMaxExitM = 1.2;
  static constexpr double kExitDoneM = 0.12;

  struct Impl;

 private:
  explicit WalkPolicyController(std::unique_ptr<Impl> impl);
  std::unique_ptr<Impl> impl_;
};

/// Walks with the policy during get-close steps and hands over to `contact` (e.g. the MPC) for
/// every other step. When the plan leaves a get-close step before the walker has stopped at
/// the stand point (the plan's get-close test is looser), walking goes on until Arrived() or
/// kMaxFinishS, so the handover happens standing still. Neither controller is owned.
/// Both knees on average more than kThighsDownM x scale below their hips (a thigh is 0.42 m:
/// about 45 degrees below level or steeper), as when standing; `pts` are one human's body
/// points (BodyJoint order); true when there are none.
inline constexpr double kThighsDownM = 0.3;
bool ThighsDown(core::Span<const Eigen::Vector3d> pts, double scale);

class WalkThenContactController : public Controller {
 public:
  WalkThenContactController(WalkPolicyController* walker, Controller* contact)
      : walker_(walker), contact_(contact) {}
  std::string name() const override { return walker_->name() + "+" + contact_->name(); }
  absl::Status Act(const Observation& obs) override;
  void Targets(double time_s, core::Span<double> ctrl) const override;
  double control_period_s() const override { return active()->control_period_s(); }
  double physics_timestep_s() const override { return active()->physics_timestep_s(); }
  bool walking() const { return walking_; }
  static constexpr double kMaxFinishS = 6.0;
  /// A get-close step that starts seated or lying is the contact controller's (it stands the
  /// human up); after standing still (pelvis above 90 % of standing height, trunk within
  /// kStoodTiltRad of upright, below 0.3 m/s) for kStoodS farther than kWalkAfterStandM from the
  /// walk point, the walker takes over.
  static constexpr double kStoodS = 0.5;
  static constexpr double kStoodTiltRad = 20.0 * M_PI / 180.0;  ///< trunk from upright, at most
  static constexpr double kWalkAfterStandM = 0.25;

 private:
  Controller* active() const { return walking_ ? static_cast<Controller*>(walker_) : contact_; }
  WalkPolicyController* walker_;
  Controller* contact_;
  bool walking_ = false;
  bool finishing_ = false;
  double finish_deadline_s_ = 0;
  double stood_since_s_ = -1;
  int step_ = -1;
};

}  // namespace simhuman::control
