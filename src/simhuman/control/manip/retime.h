#pragma once
/// Reshaping and retiming of a planned joint path (DASH Appendix A.2.2, Fig. 5): the final part
/// of the path is replaced by a cubic Hermite curve whose end tangent is a given joint-space
/// direction (the palm's approach towards the object), and the path is then timed with a
/// quadratic ("bell") speed profile that accelerates, decelerates as a human reach does, and
/// ends with a given non-zero speed (DASH: terminal palm speed 0.4 m/s).
///
/// The speed profile. With path length L (joint-space arc length, rad), duration T, terminal
/// path speed v_T and the terminal ratio r = v_T T / L, the arc length at time t (tau = t / T) is
///
///   s(t) = L sigma(tau),   sigma(tau) = (3 - r) tau^2 + (r - 2) tau^3,
///   ds/dt = (L / T) [(6 - 2 r) tau + (3 r - 6) tau^2],
///   d2s/dt2 = (L / T^2) [(6 - 2 r) + 2 (3 r - 6) tau],
///
/// the one quadratic speed with zero speed at the start, speed v_T at the end and length L.
/// r = 0 is the classic 3 tau^2 - 2 tau^3 reach (speed peak L/T * 1.5 at mid-time); for
/// 0 < r < 1.5 the speed still rises then falls to v_T (peak later and lower relative to v_T as
/// r grows); at r = 1.5 the peak reaches the end; r <= 3 keeps the motion forward everywhere.
///
/// Joint values along the path: q(t) = path(s(t)), qdot = u ds/dt, qddot = u d2s/dt2 with u the
/// unit direction of the current straight segment (tangential terms only; at a waypoint where
/// the path bends the velocity changes direction at once, which the tracker absorbs; the
/// shortcut path has few bends and the Hermite tail is dense).
///
/// Thread-safety: pure functions; a Trajectory is an immutable value.

#include <Eigen/Core>
#include <vector>

#include "simhuman/control/manip/joint_path.h"
#include "simhuman/core/status.h"

namespace simhuman::control::manip {

/// Replaces the final `fraction` of `path` (by arc length) with a cubic Hermite curve from the
/// path's point at arc length (1 - fraction) L, leaving it along the path's own direction, to
/// the path's last waypoint, arriving along `end_tangent` (a joint-space direction; only its
/// direction matters). Both tangents have magnitude fraction * L. The curve is sampled at
/// `tail_samples` points, denser towards the end (parameter 1 - (1 - k/K)^2), so the last
/// segment points along `end_tangent` to within about 1/K^2 of the curve. Waypoints before the
/// tail are kept, the endpoints exactly. The reshaped tail is not collision-checked: check it
/// (PathValid) and keep the original path when it collides.
/// Errors (InvalidArgument): a malformed path (CheckPath), a path of zero length, fraction
/// outside (0, 1], tail_samples < 2, an end_tangent of another size, zero or non-finite.
core::StatusOr<JointPath> ReshapeTail(const JointPath& path, const Eigen::VectorXd& end_tangent,
                                      double fraction = 0.1, int tail_samples = 24);

/// Unit direction of the last non-zero segment of `path` (zero vector for a path of zero length
/// or fewer than two waypoints).
Eigen::VectorXd EndDirection(const JointPath& path);

/// The joint-space direction (unit length) that moves a point with position Jacobian
/// `jacobian` (3 x n, m/rad) along `palm_direction` (world frame, any length): damped least
/// squares J^T (J J^T + damping^2 I)^-1 d. Zero vector when J^T d vanishes (a singular pose).
Eigen::VectorXd ApproachTangent(const Eigen::MatrixXd& jacobian,
                                const Eigen::Vector3d& palm_direction, double damping = 0.01);

/// The path speed (rad/s of joint-space arc length) at which moving along the unit joint
/// direction `direction` moves a point with Jacobian `jacobian` (3 x n) at `palm_speed_mps`:
/// palm_speed / |J direction|. InvalidArgument when sizes differ or |J direction| < 1e-9 (the
/// direction does not move the palm).
core::StatusOr<double> PathSpeedForPalmSpeed(const Eigen::MatrixXd& jacobian,
                                             const Eigen::VectorXd& direction,
                                             double palm_speed_mps);

/// Settings of Retime. Speeds are path speeds: rad/s of joint-space arc length.
struct RetimeOptions {
  double dt_s = 1.0 / 240.0;  ///< sample spacing of the output
  /// nominal duration (s); <= 0: L / mean_speed
  double duration_s = 0.0;
  double mean_speed = 1.0;      ///< nominal mean path speed, used when duration_s <= 0
  double terminal_speed = 0.0;  ///< path speed at the end; 0 stops there
  /// per-joint speed limits (rad/s, > 0), one per joint; empty: no limits
  Eigen::VectorXd max_velocity;

  /// InvalidArgument naming the field when out of range.
  absl::Status Validate() const;
};

/// A time-parameterised path: the quadratic speed profile over a joint path (formula above),
/// with samples every dt_s. Immutable; build it with Retime.
class Trajectory {
 public:
  /// Joint positions (rad), velocities (rad/s) and accelerations (rad/s^2) at one time.
  struct Point {
    Eigen::VectorXd q, qdot, qddot;
  };

  /// Exact evaluation at time `t_s`, clamped to [0, duration_s()] (after the end: the end
  /// state, including the terminal velocity and deceleration).
  Point Sample(double t_s) const;
  /// Arc length s(t) (rad) at time t_s (clamped as in Sample).
  double PathPosition(double t_s) const;
  /// Path speed ds/dt (rad/s) at time t_s (clamped as in Sample).
  double PathSpeed(double t_s) const;

  /// Duration T (s), after any shortening or stretching by Retime.
  double duration_s() const { return duration_s_; }
  /// Sample spacing (s).
  double dt_s() const { return dt_s_; }
  /// Path length L (rad of joint-space arc length).
  double length() const { return length_; }
  /// the terminal ratio r = v_T T / L of the profile (0 when the path stops)
  double terminal_ratio() const { return ratio_; }
  /// Number of joints.
  int num_dofs() const { return path_.num_dofs(); }
  /// The timed path (the input without repeated waypoints).
  const JointPath& path() const { return path_; }

  /// Sample times: k * dt_s for k = 0 .. while < duration_s, then duration_s itself (the last
  /// spacing may be shorter than dt_s); one sample at 0 for a path of zero length.
  const std::vector<double>& times() const { return times_; }
  /// Positions (rad) at times(), one per sample.
  const std::vector<Eigen::VectorXd>& positions() const { return q_; }
  /// Velocities (rad/s) at times().
  const std::vector<Eigen::VectorXd>& velocities() const { return qdot_; }
  /// Accelerations (rad/s^2, tangential) at times().
  const std::vector<Eigen::VectorXd>& accelerations() const { return qddot_; }

 private:
  friend core::StatusOr<Trajectory> Retime(const JointPath& path, const RetimeOptions& options);
  Trajectory() = default;

  JointPath path_;
  std::vector<double> cumulative_;
  double length_ = 0, duration_s_ = 0, dt_s_ = 0, ratio_ = 0;
  std::vector<double> times_;
  std::vector<Eigen::VectorXd> q_, qdot_, qddot_;
};

/// Times `path` with the quadratic speed profile (formula above). The duration starts at the
/// nominal one (options.duration_s or L / mean_speed). When the terminal speed would need
/// r > 1.5 at that duration (the profile would not decelerate), the duration is shortened to
/// 1.5 L / v_T. When a joint would exceed max_velocity it is stretched (bisection on T, keeping
/// r <= 3) until every joint stays within its limit, checked exactly per segment.
/// Errors (InvalidArgument): bad options; a malformed path; max_velocity of another size; a
/// terminal speed that moves some joint along the last segment faster than its limit (naming
/// the joint); a terminal speed on a path of zero length. FailedPrecondition: the limits cannot
/// be met with the terminal speed at any duration (naming the joint).
core::StatusOr<Trajectory> Retime(const JointPath& path, const RetimeOptions& options = {});

}  // namespace simhuman::control::manip
