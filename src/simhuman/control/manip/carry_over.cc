#include "simhuman/control/manip/carry_over.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>

namespace simhuman::control::manip {
namespace {

// no joint moves further than this between two palm poses 2 cm apart unless the IK flipped
constexpr double kMaxStepRad = 0.3;

}  // namespace

std::vector<PalmPose> OverArcPalmPath(const PalmPose& from, const PalmPose& to,
                                      const Eigen::Vector3d& held, double lift_m, double step_m) {
  // the held point's arc: a cubic Bezier with both inner points at height h peaks at
  // (z0 + z1) / 8 + 3 h / 4 midway
  const Eigen::Vector3d p0 = from.pos + from.rot * held, p3 = to.pos + to.rot * held;
  const double top = std::max(p0.z(), p3.z()) + std::max(lift_m, 0.0);
  const double h = (top - (p0.z() + p3.z()) / 8) / 0.75;
  const Eigen::Vector3d p1(p0.x(), p0.y(), h), p2(p3.x(), p3.y(), h);
  auto at = [&](double t) {
    const double u = 1 - t;
    return Eigen::Vector3d(u * u * u * p0 + 3 * u * u * t * p1 + 3 * u * t * t * p2 +
                           t * t * t * p3);
  };
  // the parameter sampled finely enough that no two poses lie further apart than step_m (the
  // curve's speed varies along it; its fastest from a fine polyline)
  constexpr int kFine = 200;
  double fastest = 0;
  for (int i = 1; i <= kFine; ++i)
    fastest = std::max(fastest, (at(double(i) / kFine) - at(double(i - 1) / kFine)).norm() * kFine);
  const int n = std::max(1, static_cast<int>(std::ceil(fastest / std::max(step_m, 1e-3))));
  const Eigen::Quaterniond q0(from.rot), q1(to.rot);
  std::vector<PalmPose> poses;
  poses.reserve(n);
  for (int i = 1; i <= n; ++i) {
    const double t = double(i) / n;
    PalmPose p;
    p.rot = i == n ? to.rot : q0.slerp(t, q1).toRotationMatrix();
    p.pos = (i == n ? p3 : at(t)) - p.rot * held;
    poses.push_back(p);
  }
  return poses;
}

core::StatusOr<ArmMotion> PlanCarryOver(const mjModel* m, const mjData* d, mjData* s,
                                        const ArmChain& arm, const PalmPose& from,
                                        const PalmPose& goal, const Eigen::Vector3d& held,
                                        const CarryOverOptions& co, const ArmMotionOptions& o,
                                        const Eigen::VectorXd& goal_q) {
  if (co.lift_m.empty()) return absl::InvalidArgumentError("plan failure: no arc heights to try");
  ArmAlongOptions along;
  along.max_step_rad = kMaxStepRad;
  along.via_tol_rot_rad = co.tilt_tol_rad;
  along.rest_to = goal_q;
  auto arc = [&](double lift) {
    return PlanArmAlong(m, d, s, arm, OverArcPalmPath(from, goal, held, lift, co.step_m), o, along);
  };
  core::StatusOr<ArmMotion> last = absl::NotFoundError("plan failure: no arc tried");
  for (double lift : co.lift_m) {
    last = arc(lift);
    if (!last.ok()) continue;
    if (co.margin_m > 0) {
      core::StatusOr<ArmMotion> higher = arc(lift + co.margin_m);
      if (higher.ok()) return higher;
    }
    return last;
  }
  return last;
}

}  // namespace simhuman::control::manip
