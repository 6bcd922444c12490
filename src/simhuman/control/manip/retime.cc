#include "simhuman/control/manip/retime.h"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <utility>

#include "absl/strings/str_cat.h"
#include "simhuman/core/check.h"

namespace simhuman::control::manip {
namespace {

// r above this: the profile no longer decelerates before the end
constexpr double kBellRatio = 1.5;
// r above this: the speed would turn negative on the way
constexpr double kMaxRatio = 3.0;
// relative slack when comparing a speed with its limit
constexpr double kLimitSlack = 1e-9;

// the normalised profile sigma(tau) of the header, for terminal ratio r
double Sigma(double tau, double r) { return (3 - r) * tau * tau + (r - 2) * tau * tau * tau; }
double DSigma(double tau, double r) { return (6 - 2 * r) * tau + (3 * r - 6) * tau * tau; }
double DDSigma(double tau, double r) { return (6 - 2 * r) + 2 * (3 * r - 6) * tau; }

// tau in [0, 1] with Sigma(tau, r) = target (sigma is non-decreasing for 0 <= r <= 3)
double TauAt(double target, double r) {
  double lo = 0, hi = 1;
  for (int i = 0; i < 60; ++i) {
    const double mid = 0.5 * (lo + hi);
    (Sigma(mid, r) < target ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

// largest DSigma over [ta, tb]: a parabola in tau, concave for r < 2
double MaxDSigma(double ta, double tb, double r) {
  double m = std::max(DSigma(ta, r), DSigma(tb, r));
  if (r < 2) {
    const double peak = (3 - r) / (6 - 3 * r);
    if (peak > ta && peak < tb) m = std::max(m, DSigma(peak, r));
  }
  return m;
}

// consecutive exact repeats removed (they would have no direction)
JointPath WithoutRepeats(const JointPath& path) {
  JointPath out;
  for (const Eigen::VectorXd& w : path.waypoints) {
    if (out.waypoints.empty() || (w - out.waypoints.back()).norm() > 0) out.waypoints.push_back(w);
  }
  return out;
}

// the worst ratio |joint speed| / limit over the whole trajectory, exact per segment, and its
// joint
std::pair<double, int> WorstSpeedRatio(const JointPath& path, const std::vector<double>& cum,
                                       double duration_s, double r, const Eigen::VectorXd& vmax) {
  const double length = cum.back();
  std::pair<double, int> worst{0.0, 0};
  for (int k = 0; k + 1 < path.size(); ++k) {
    const double seg = cum[k + 1] - cum[k];
    if (seg <= 0) continue;
    const Eigen::VectorXd u = (path.waypoints[k + 1] - path.waypoints[k]) / seg;
    const double ta = TauAt(cum[k] / length, r);
    const double tb = TauAt(cum[k + 1] / length, r);
    const double speed = length / duration_s * MaxDSigma(ta, tb, r);
    for (int j = 0; j < u.size(); ++j) {
      const double ratio = std::abs(u[j]) * speed / vmax[j];
      if (ratio > worst.first) worst = {ratio, j};
    }
  }
  return worst;
}

// the shortest duration >= duration_s at which every joint stays within vmax (bisection);
// FailedPrecondition when r would have to pass kMaxRatio
core::StatusOr<double> StretchForLimits(const JointPath& path, const std::vector<double>& cum,
                                        double duration_s, double v_end,
                                        const Eigen::VectorXd& vmax) {
  const double length = cum.back();
  auto ratio_at = [&](double t) { return WorstSpeedRatio(path, cum, t, v_end * t / length, vmax); };
  std::pair<double, int> worst = ratio_at(duration_s);
  if (worst.first <= 1 + kLimitSlack) return duration_s;
  const double longest =
      v_end > 0 ? kMaxRatio * length / v_end : std::numeric_limits<double>::infinity();
  double lo = duration_s, hi = duration_s;
  for (int i = 0;; ++i) {
    if (hi >= longest || i >= 64) {
      return absl::FailedPreconditionError(absl::StrCat(
          "retime: joint ", worst.second, " exceeds its velocity limit ", vmax[worst.second],
          " rad/s by a factor ", worst.first, " even at the longest duration (", hi,
          " s) that keeps the terminal path speed ", v_end, " rad/s"));
    }
    lo = hi;
    hi = std::min(2 * hi, longest);
    worst = ratio_at(hi);
    if (worst.first <= 1 + kLimitSlack) break;
  }
  for (int i = 0; i < 50; ++i) {
    const double mid = 0.5 * (lo + hi);
    (ratio_at(mid).first <= 1 + kLimitSlack ? hi : lo) = mid;
  }
  return hi;
}

}  // namespace

core::StatusOr<JointPath> ReshapeTail(const JointPath& path, const Eigen::VectorXd& end_tangent,
                                      double fraction, int tail_samples) {
  SH_RETURN_IF_ERROR(CheckPath(path));
  if (!(fraction > 0 && fraction <= 1)) {
    return absl::InvalidArgumentError(
        absl::StrCat("reshape: fraction = ", fraction, " must be in (0, 1]"));
  }
  if (tail_samples < 2) {
    return absl::InvalidArgumentError(
        absl::StrCat("reshape: tail_samples = ", tail_samples, " must be >= 2"));
  }
  if (end_tangent.size() != path.num_dofs() || !end_tangent.allFinite() ||
      end_tangent.norm() == 0) {
    return absl::InvalidArgumentError(
        absl::StrCat("reshape: end_tangent must be a finite, non-zero vector of ", path.num_dofs(),
                     " joints (got ", end_tangent.size(), " entries)"));
  }
  const JointPath clean = WithoutRepeats(path);
  const std::vector<double> cum = CumulativeLengths(clean);
  const double length = cum.back();
  if (length <= 0) return absl::InvalidArgumentError("reshape: the path has zero length");

  // the tail starts at arc length s0, on segment i0, leaving along that segment
  const double s0 = (1 - fraction) * length;
  const int i0 = SegmentAt(cum, s0);
  const Eigen::VectorXd p0 = PointAt(clean, s0, &cum);
  const Eigen::VectorXd& p1 = clean.waypoints.back();
  const double magnitude = fraction * length;
  const Eigen::VectorXd m0 =
      (clean.waypoints[i0 + 1] - clean.waypoints[i0]).normalized() * magnitude;
  const Eigen::VectorXd m1 = end_tangent.normalized() * magnitude;

  JointPath out;
  out.waypoints.assign(clean.waypoints.begin(), clean.waypoints.begin() + i0 + 1);
  if ((p0 - out.waypoints.back()).norm() > 1e-12) out.waypoints.push_back(p0);
  for (int k = 1; k <= tail_samples; ++k) {
    const double a = 1.0 - static_cast<double>(k) / tail_samples;
    const double u = 1.0 - a * a;  // denser towards the end
    const double u2 = u * u, u3 = u2 * u;
    out.waypoints.push_back((2 * u3 - 3 * u2 + 1) * p0 + (u3 - 2 * u2 + u) * m0 +
                            (-2 * u3 + 3 * u2) * p1 + (u3 - u2) * m1);
  }
  out.waypoints.back() = p1;
  return out;
}

Eigen::VectorXd EndDirection(const JointPath& path) {
  for (int k = path.size() - 1; k >= 1; --k) {
    const Eigen::VectorXd d = path.waypoints[k] - path.waypoints[k - 1];
    if (d.norm() > 0) return d.normalized();
  }
  return Eigen::VectorXd::Zero(path.num_dofs());
}

Eigen::VectorXd ApproachTangent(const Eigen::MatrixXd& jacobian,
                                const Eigen::Vector3d& palm_direction, double damping) {
  SH_CHECK(jacobian.rows() == 3, "ApproachTangent needs a 3 x n position Jacobian");
  const Eigen::Matrix3d a =
      jacobian * jacobian.transpose() + damping * damping * Eigen::Matrix3d::Identity();
  const Eigen::VectorXd dq = jacobian.transpose() * a.ldlt().solve(palm_direction);
  const double norm = dq.norm();
  if (!(norm > 1e-12)) return Eigen::VectorXd::Zero(jacobian.cols());
  return dq / norm;
}

core::StatusOr<double> PathSpeedForPalmSpeed(const Eigen::MatrixXd& jacobian,
                                             const Eigen::VectorXd& direction,
                                             double palm_speed_mps) {
  if (jacobian.rows() != 3 || jacobian.cols() != direction.size()) {
    return absl::InvalidArgumentError(absl::StrCat("palm speed: the Jacobian is ", jacobian.rows(),
                                                   " x ", jacobian.cols(), ", expected 3 x ",
                                                   direction.size(), " (the direction's size)"));
  }
  if (!(palm_speed_mps >= 0 && std::isfinite(palm_speed_mps))) {
    return absl::InvalidArgumentError(
        absl::StrCat("palm speed: ", palm_speed_mps, " m/s must be finite and >= 0"));
  }
  const double norm = direction.norm();
  const double gain = norm > 0 ? (jacobian * direction).norm() / norm : 0.0;
  if (!(gain >= 1e-9)) {
    return absl::InvalidArgumentError(
        "palm speed: the joint direction does not move the palm (|J u| < 1e-9 m/rad)");
  }
  return palm_speed_mps / gain;
}

absl::Status RetimeOptions::Validate() const {
  if (!(dt_s > 0 && dt_s <= 1.0)) {
    return absl::InvalidArgumentError(absl::StrCat("retime: dt_s = ", dt_s, " must be in (0, 1]"));
  }
  if (!std::isfinite(duration_s)) {
    return absl::InvalidArgumentError("retime: duration_s must be finite (<= 0: from mean_speed)");
  }
  if (duration_s <= 0 && !(mean_speed > 0 && std::isfinite(mean_speed))) {
    return absl::InvalidArgumentError(absl::StrCat("retime: mean_speed = ", mean_speed,
                                                   " rad/s must be > 0 when duration_s <= 0"));
  }
  if (!(terminal_speed >= 0 && std::isfinite(terminal_speed))) {
    return absl::InvalidArgumentError(
        absl::StrCat("retime: terminal_speed = ", terminal_speed, " rad/s must be >= 0"));
  }
  for (int j = 0; j < max_velocity.size(); ++j) {
    if (!(max_velocity[j] > 0)) {
      return absl::InvalidArgumentError(absl::StrCat("retime: max_velocity of joint ", j, " = ",
                                                     max_velocity[j], " rad/s must be > 0"));
    }
  }
  return absl::OkStatus();
}

double Trajectory::PathPosition(double t_s) const {
  if (duration_s_ <= 0) return 0;
  const double tau = std::clamp(t_s / duration_s_, 0.0, 1.0);
  return length_ * Sigma(tau, ratio_);
}

double Trajectory::PathSpeed(double t_s) const {
  if (duration_s_ <= 0) return 0;
  const double tau = std::clamp(t_s / duration_s_, 0.0, 1.0);
  return length_ / duration_s_ * DSigma(tau, ratio_);
}

Trajectory::Point Trajectory::Sample(double t_s) const {
  Point p;
  const int n = num_dofs();
  if (duration_s_ <= 0 || path_.size() < 2) {
    p.q = path_.waypoints.front();
    p.qdot = p.qddot = Eigen::VectorXd::Zero(n);
    return p;
  }
  const double tau = std::clamp(t_s / duration_s_, 0.0, 1.0);
  const double s = length_ * Sigma(tau, ratio_);
  const double sdot = length_ / duration_s_ * DSigma(tau, ratio_);
  const double sddot = length_ / (duration_s_ * duration_s_) * DDSigma(tau, ratio_);
  const int k = SegmentAt(cumulative_, s);
  const double seg = cumulative_[k + 1] - cumulative_[k];
  const Eigen::VectorXd u = (path_.waypoints[k + 1] - path_.waypoints[k]) / seg;
  p.q = path_.waypoints[k] + std::clamp(s - cumulative_[k], 0.0, seg) * u;
  p.qdot = sdot * u;
  p.qddot = sddot * u;
  return p;
}

core::StatusOr<Trajectory> Retime(const JointPath& path, const RetimeOptions& options) {
  SH_RETURN_IF_ERROR(options.Validate());
  SH_RETURN_IF_ERROR(CheckPath(path));
  const int n = path.num_dofs();
  const Eigen::VectorXd& vmax = options.max_velocity;
  if (vmax.size() != 0 && vmax.size() != n) {
    return absl::InvalidArgumentError(absl::StrCat("retime: max_velocity has ", vmax.size(),
                                                   " entries, the path has ", n, " joints"));
  }
  Trajectory traj;
  traj.path_ = WithoutRepeats(path);
  traj.cumulative_ = CumulativeLengths(traj.path_);
  traj.length_ = traj.cumulative_.back();
  traj.dt_s_ = options.dt_s;
  const double length = traj.length_;
  const double v_end = options.terminal_speed;
  if (length <= 0) {
    if (v_end > 0) {
      return absl::InvalidArgumentError(
          "retime: a terminal speed was asked for on a path of zero length");
    }
    traj.times_ = {0.0};
    traj.q_ = {traj.path_.waypoints.front()};
    traj.qdot_ = traj.qddot_ = {Eigen::VectorXd::Zero(n)};
    return traj;
  }

  double duration = options.duration_s > 0 ? options.duration_s : length / options.mean_speed;
  if (v_end * duration / length > kBellRatio) duration = kBellRatio * length / v_end;
  if (vmax.size() == n) {
    const Eigen::VectorXd u_end = EndDirection(traj.path_);
    for (int j = 0; j < n; ++j) {
      if (v_end * std::abs(u_end[j]) > vmax[j] * (1 + kLimitSlack)) {
        return absl::InvalidArgumentError(absl::StrCat(
            "retime: the terminal path speed ", v_end, " rad/s moves joint ", j, " at ",
            v_end * std::abs(u_end[j]), " rad/s, above its limit ", vmax[j], " rad/s"));
      }
    }
    SH_ASSIGN_OR_RETURN(duration,
                        StretchForLimits(traj.path_, traj.cumulative_, duration, v_end, vmax));
  }
  traj.duration_s_ = duration;
  traj.ratio_ = v_end * duration / length;
  SH_CHECK(traj.ratio_ >= 0 && traj.ratio_ <= kMaxRatio + 1e-9, "terminal ratio out of range");

  for (int k = 0; k * options.dt_s < duration - 1e-12; ++k) traj.times_.push_back(k * options.dt_s);
  traj.times_.push_back(duration);
  for (const double t : traj.times_) {
    Trajectory::Point p = traj.Sample(t);
    traj.q_.push_back(std::move(p.q));
    traj.qdot_.push_back(std::move(p.qdot));
    traj.qddot_.push_back(std::move(p.qddot));
  }
  return traj;
}

}  // namespace simhuman::control::manip
