#include "simhuman/control/manip/tracker.h"

#include <algorithm>
#include <cmath>
#include <utility>

#include "absl/strings/str_cat.h"
#include "simhuman/core/check.h"

namespace simhuman::control::manip {

Eigen::VectorXd NextVelocity(const Eigen::VectorXd& q, const Eigen::VectorXd& qdot,
                             const Eigen::VectorXd& q_ref, const Eigen::VectorXd& qdot_ref,
                             double kp, double kd, double dt_s) {
  SH_CHECK(q.size() == qdot.size() && q.size() == q_ref.size() && q.size() == qdot_ref.size(),
           "NextVelocity: vectors of different sizes");
  return qdot_ref - dt_s * kp * (q - q_ref) - (dt_s * kd - 1.0) * (qdot - qdot_ref);
}

absl::Status TrackerGains::Validate() const {
  const std::pair<const char*, double> fields[] = {{"kp", kp},
                                                   {"kd", kd},
                                                   {"ki", ki},
                                                   {"integral_limit_rad_s", integral_limit_rad_s},
                                                   {"min_inertia", min_inertia}};
  for (const auto& [name, value] : fields) {
    if (!(value >= 0 && std::isfinite(value))) {
      return absl::InvalidArgumentError(
          absl::StrCat("tracker: ", name, " = ", value, " must be finite and >= 0"));
    }
  }
  return absl::OkStatus();
}

JointTracker::JointTracker(int num_dofs, const TrackerGains& gains)
    : gains_(gains), integral_(Eigen::VectorXd::Zero(num_dofs)) {
  SH_CHECK(num_dofs > 0, "JointTracker needs at least one joint");
  SH_CHECK(gains.Validate().ok(), "JointTracker: invalid gains (TrackerGains::Validate)");
}

Eigen::VectorXd JointTracker::DesiredAcceleration(const Eigen::VectorXd& q,
                                                  const Eigen::VectorXd& qdot,
                                                  const Eigen::VectorXd& q_ref,
                                                  const Eigen::VectorXd& qdot_ref,
                                                  const Eigen::VectorXd& qddot_ref, double dt_s) {
  const int n = num_dofs();
  SH_CHECK(q.size() == n && qdot.size() == n && q_ref.size() == n && qdot_ref.size() == n &&
               qddot_ref.size() == n,
           "JointTracker: vectors of another size than num_dofs()");
  SH_CHECK(dt_s > 0, "JointTracker: dt_s must be > 0");
  const Eigen::VectorXd e = q_ref - q;
  const double limit = gains_.integral_limit_rad_s;
  integral_ = (integral_ + dt_s * e).cwiseMax(-limit).cwiseMin(limit);
  return qddot_ref + gains_.kp * e + gains_.kd * (qdot_ref - qdot) + gains_.ki * integral_;
}

core::StatusOr<InverseDynamics> InverseDynamics::Create(const mjModel* m, std::vector<int> dofs) {
  SH_CHECK(m != nullptr, "InverseDynamics needs a model");
  if (dofs.empty()) return absl::InvalidArgumentError("inverse dynamics: no dofs");
  std::vector<bool> seen(m->nv, false);
  for (size_t i = 0; i < dofs.size(); ++i) {
    const int dof = dofs[i];
    if (dof < 0 || dof >= m->nv) {
      return absl::InvalidArgumentError(absl::StrCat("inverse dynamics: dof ", dof, " (entry ", i,
                                                     ") is outside [0, ", m->nv, ")"));
    }
    if (seen[dof]) {
      return absl::InvalidArgumentError(
          absl::StrCat("inverse dynamics: dof ", dof, " appears twice"));
    }
    seen[dof] = true;
  }
  return InverseDynamics(m, std::move(dofs));
}

InverseDynamics::InverseDynamics(const mjModel* m, std::vector<int> dofs)
    : model_(m), dofs_(std::move(dofs)), acc_(m->nv, 0.0), force_(m->nv, 0.0) {}

Eigen::VectorXd InverseDynamics::Torque(const mjData* d, const Eigen::VectorXd& qacc_des) {
  const int n = static_cast<int>(dofs_.size());
  SH_CHECK(qacc_des.size() == n, "InverseDynamics::Torque: one acceleration per dof");
  std::fill(acc_.begin(), acc_.end(), 0.0);
  for (int i = 0; i < n; ++i) acc_[dofs_[i]] = qacc_des[i];
  mj_mulM(model_, d, force_.data(), acc_.data());
  // Euler and implicit integrate joint damping implicitly: (M + h D) qacc = f
  const bool implicit_damping = model_->opt.integrator != mjINT_RK4;
  Eigen::VectorXd tau(n);
  for (int i = 0; i < n; ++i) {
    const int dof = dofs_[i];
    tau[i] = force_[dof] + d->qfrc_bias[dof] - d->qfrc_passive[dof];
    if (implicit_damping) tau[i] += model_->opt.timestep * model_->dof_damping[dof] * qacc_des[i];
  }
  return tau;
}

void InverseDynamics::Apply(mjData* d, const Eigen::VectorXd& tau) const {
  SH_CHECK(tau.size() == static_cast<int>(dofs_.size()), "InverseDynamics::Apply: size");
  for (size_t i = 0; i < dofs_.size(); ++i) d->qfrc_applied[dofs_[i]] = tau[static_cast<int>(i)];
}

}  // namespace simhuman::control::manip
