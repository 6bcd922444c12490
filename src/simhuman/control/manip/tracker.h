#pragma once
/// Tracking a retimed arm trajectory in MuJoCo (DASH Appendix A.2.3): a PD law that gives the
/// desired joint velocity of the next step (the seed's Eq. 2), a PID acceleration law with a
/// clamped integrator (an unmodelled held object otherwise makes the arm sag), and inverse
/// dynamics that turns a desired acceleration of the arm's dofs into joint torques.
///
/// Typical step (torques through qfrc_applied, or through motors with unit gear via ctrl):
///
///   mj_step1(m, d);                                   // qM, qfrc_bias, qfrc_passive
///   Trajectory::Point ref = traj.Sample(t);
///   Eigen::VectorXd a = tracker.DesiredAcceleration(q, qdot, ref.q, ref.qdot, ref.qddot, dt);
///   id.Apply(d, id.Torque(d, a));
///   mj_step2(m, d);
///
/// Thread-safety: NextVelocity is pure; JointTracker and InverseDynamics hold per-instance
/// state (one per arm and thread); the mjModel is only read.

#include <mujoco/mujoco.h>

#include <Eigen/Core>
#include <vector>

#include "simhuman/core/status.h"

namespace simhuman::control::manip {

/// The seed's Eq. 2, the desired joint velocity of the next step:
///
///   qdot+ = qdot_ref - dt kp (q - q_ref) - (dt kd - 1) (qdot - qdot_ref),
///
/// with continuous-time gains kp (1/s^2) and kd (1/s) and step dt_s (s). With qdot_ref = 0 this
/// is Eq. 2, qdot+ = -Kp (q - q_ref) - (Kd - 1) qdot, for its per-step gains Kp = dt kp and
/// Kd = dt kd. Realise it with InverseDynamics::Torque(d, (qdot+ - qdot) / dt); the implied
/// acceleration is -kp (q - q_ref) - kd (qdot - qdot_ref) (no reference feed-forward; use
/// JointTracker for that). All vectors must have one size (a bug otherwise).
Eigen::VectorXd NextVelocity(const Eigen::VectorXd& q, const Eigen::VectorXd& qdot,
                             const Eigen::VectorXd& q_ref, const Eigen::VectorXd& qdot_ref,
                             double kp, double kd, double dt_s);

/// Gains of JointTracker (the settings that carried up to 5 kg objects in the experiments).
struct TrackerGains {
  double kp = 600.0;   ///< 1/s^2
  double kd = 49.0;    ///< 1/s (about critical damping for kp = 600)
  double ki = 2500.0;  ///< 1/s^3; 0 switches the integral term off
  /// per-joint clamp of the error integral (rad s): bounds the integral term to
  /// ki * integral_limit (rad/s^2) and its wind-up
  double integral_limit_rad_s = 0.1;
  /// kg m^2: each joint's own inertia in the inverse dynamics is taken as at least this, i.e.
  /// the light forearm and wrist joints get at least kp * min_inertia N m/rad of stiffness (a
  /// held object, which the inverse dynamics does not model, outweighs their own inertia many
  /// times and they gave way under it; a person stiffens the wrist). 0 leaves the model alone.
  double min_inertia = 0.03;

  /// InvalidArgument naming the field when out of range.
  absl::Status Validate() const;
};

/// PID acceleration law with feed-forward, for one arm:
///
///   e = q_ref - q,  I <- clamp(I + e dt, -limit, limit),
///   qddot_des = qddot_ref + kp e + kd (qdot_ref - qdot) + ki I.
///
/// Not thread-safe (holds the integral).
class JointTracker {
 public:
  /// `num_dofs` joints; gains must be valid (Validate(); a bug otherwise).
  JointTracker(int num_dofs, const TrackerGains& gains = {});

  /// Updates the integral over `dt_s` and returns the desired acceleration (rad/s^2). Vectors
  /// of num_dofs() entries (a bug otherwise).
  Eigen::VectorXd DesiredAcceleration(const Eigen::VectorXd& q, const Eigen::VectorXd& qdot,
                                      const Eigen::VectorXd& q_ref, const Eigen::VectorXd& qdot_ref,
                                      const Eigen::VectorXd& qddot_ref, double dt_s);

  /// Zeroes the integral (at the start of a new trajectory).
  void Reset() { integral_.setZero(); }
  /// The clamped error integral (rad s), per joint.
  const Eigen::VectorXd& integral() const { return integral_; }
  /// The gains it was made with.
  const TrackerGains& gains() const { return gains_; }
  /// Number of joints.
  int num_dofs() const { return static_cast<int>(integral_.size()); }

 private:
  TrackerGains gains_;
  Eigen::VectorXd integral_;
};

/// Inverse dynamics restricted to a set of dofs (an arm's): the generalized forces on those
/// dofs that give them a desired acceleration while the other dofs are given zero acceleration,
///
///   tau = (M a)[dofs] + qfrc_bias[dofs] - qfrc_passive[dofs] (+ h damping[dofs] a[dofs]),
///
/// where a holds qacc_des on the dofs and 0 elsewhere. The last term is for MuJoCo's Euler and
/// implicit integrators, which treat joint damping implicitly ((M + h D) qacc = f). Contact and
/// limit forces are not compensated (the PID absorbs them). Holds scratch space: one instance
/// per thread.
class InverseDynamics {
 public:
  /// `m` must outlive the instance. InvalidArgument when `dofs` is empty, has repeats, or an
  /// index outside [0, nv) (naming it).
  static core::StatusOr<InverseDynamics> Create(const mjModel* m, std::vector<int> dofs);

  /// The torques (N m for hinges), one per dof in dofs() order, for accelerations `qacc_des`
  /// (rad/s^2, same order). `d` must hold the current state's qM, qfrc_bias and qfrc_passive,
  /// as left by mj_step1 or mj_forward. Size mismatch is a bug.
  Eigen::VectorXd Torque(const mjData* d, const Eigen::VectorXd& qacc_des);

  /// Writes `tau` into d->qfrc_applied at the dofs (other entries untouched).
  void Apply(mjData* d, const Eigen::VectorXd& tau) const;

  /// The dof indices (into qvel, qacc, qfrc_*), in torque order.
  const std::vector<int>& dofs() const { return dofs_; }

 private:
  InverseDynamics(const mjModel* m, std::vector<int> dofs);
  const mjModel* model_;
  std::vector<int> dofs_;
  std::vector<mjtNum> acc_, force_;  // nv each
};

}  // namespace simhuman::control::manip
