#include "simhuman/control/manip/arm_ik.h"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>

#include "simhuman/control/manip/arm_collision.h"
#include "simhuman/core/check.h"
#include "simhuman/world/hand.h"

namespace simhuman::control::manip {
namespace {

constexpr const char* kArmJoints[ArmChain::kDofs] = {
    "shoulder_x", "shoulder_y", "shoulder_z", "elbow", "forearm_rot", "wrist_flex", "wrist_dev"};

Eigen::Matrix3d BodyRot(const mjData* d, int body) {
  return Eigen::Map<const Eigen::Matrix<double, 3, 3, Eigen::RowMajor>>(d->xmat + 9 * body);
}

// the rotation vector (axis x angle) of `r`
Eigen::Vector3d RotVec(const Eigen::Matrix3d& r) {
  const Eigen::AngleAxisd aa(r);
  return aa.axis() * aa.angle();
}

}  // namespace

Eigen::VectorXd ArmChain::Get(const mjData* d) const {
  Eigen::VectorXd q(kDofs);
  for (int i = 0; i < kDofs; ++i) q[i] = d->qpos[qpos[i]];
  return q;
}

void ArmChain::Set(mjData* d, const Eigen::VectorXd& q) const {
  SH_CHECK(q.size() == kDofs, "an arm pose has 7 angles");
  for (int i = 0; i < kDofs; ++i) d->qpos[qpos[i]] = q[i];
}

Eigen::VectorXd ArmChain::Clamp(const Eigen::VectorXd& q) const {
  Eigen::VectorXd out = q;
  for (int i = 0; i < kDofs; ++i) out[i] = std::clamp(q[i], lo[i], hi[i]);
  return out;
}

core::StatusOr<ArmChain> MakeArmChain(const world::SimWorld& world, int agent, bool right) {
  const mjModel* m = world.model();
  const world::AgentIndex& ix = world.agent(agent);
  const std::string prefix = world::AgentPrefix(agent) + (right ? "right_" : "left_");
  const int forearm = mj_name2id(m, mjOBJ_JOINT, (prefix + "forearm_rot").c_str());
  if (forearm < 0) {
    return absl::FailedPreconditionError(
        "human " + std::to_string(agent) + " (kind '" + ix.kind + "') has no dexterous " +
        (right ? "right" : "left") +
        " hand; kinds with one: humanoid_right_hand (right), humanoid_hands (both)");
  }
  ArmChain arm;
  arm.agent = agent;
  arm.right = right;
  for (int i = 0; i < ArmChain::kDofs; ++i) {
    const std::string name = prefix + kArmJoints[i];
    const int j = mj_name2id(m, mjOBJ_JOINT, name.c_str());
    const int a = mj_name2id(m, mjOBJ_ACTUATOR, name.c_str());
    if (j < 0 || a < 0) return absl::InternalError("arm joint missing: " + name);
    arm.qpos[i] = m->jnt_qposadr[j];
    arm.dof[i] = m->jnt_dofadr[j];
    arm.actuator[i] = a;
    arm.lo[i] = m->jnt_range[2 * j];
    arm.hi[i] = m->jnt_range[2 * j + 1];
  }
  arm.palm_site = mj_name2id(
      m, mjOBJ_SITE,
      (world::AgentPrefix(agent) + "pt_" + (right ? "right_" : "left_") + "palm").c_str());
  arm.hand_body = mj_name2id(m, mjOBJ_BODY, (prefix + "hand").c_str());
  const int upper = mj_name2id(m, mjOBJ_BODY, (prefix + "upper_arm").c_str());
  if (arm.palm_site < 0 || arm.hand_body < 0 || upper < 0) {
    return absl::InternalError("arm bodies or palm site missing for " + prefix);
  }
  // the upper arm's subtree: bodies are numbered depth-first, so it is a contiguous run
  for (int b = upper; b < m->nbody; ++b) {
    int p = b;
    while (p > 0 && p != upper) p = m->body_parentid[p];
    if (p != upper) break;
    arm.bodies.push_back(b);
  }
  for (const world::HandJoint& h : world::HandJoints()) {
    const std::string name = prefix + h.name;
    if (name == prefix + "forearm_rot" || name == prefix + "wrist_flex" ||
        name == prefix + "wrist_dev") {
      continue;
    }
    arm.finger_actuators.push_back(mj_name2id(m, mjOBJ_ACTUATOR, name.c_str()));
  }
  return arm;
}

namespace {

// `t` turned about the vertical line through t.yaw_free_about by the yaw that brings its
// rotation nearest `hand` (the turn maximising trace(Rz(psi) t.rot hand^T))
PalmPose TurnedNearest(const PalmPose& t, const Eigen::Matrix3d& hand) {
  const Eigen::Matrix3d m = t.rot * hand.transpose();
  const double psi = std::atan2(m(0, 1) - m(1, 0), m(0, 0) + m(1, 1));
  const Eigen::Matrix3d rz = Eigen::AngleAxisd(psi, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  PalmPose out;
  out.rot = rz * t.rot;
  out.pos = *t.yaw_free_about + rz * (t.pos - *t.yaw_free_about);
  return out;
}

}  // namespace

IkResult SolvePalmIk(const mjModel* m, mjData* d, const ArmChain& arm, const PalmPose& target,
                     const Eigen::VectorXd& q0, const Eigen::VectorXd& rest, const IkOptions& o) {
  constexpr int n = ArmChain::kDofs;
  std::vector<mjtNum> jacp(3 * m->nv), jacr(3 * m->nv);
  IkResult r;
  r.q = arm.Clamp(q0);
  double best = 1e300;
  Eigen::VectorXd q = r.q;
  for (int it = 0; it < o.max_iterations; ++it) {
    arm.Set(d, q);
    mj_kinematics(m, d);
    mj_comPos(m, d);
    const Eigen::Vector3d p(d->site_xpos + 3 * arm.palm_site);
    const Eigen::Matrix3d hand = BodyRot(d, arm.hand_body);
    const PalmPose goal = target.yaw_free_about ? TurnedNearest(target, hand) : target;
    const Eigen::Vector3d ep = goal.pos - p;
    const Eigen::Vector3d er = RotVec(goal.rot * hand.transpose());
    const double score = ep.norm() + o.rot_weight_m * er.norm();
    if (score < best) {
      best = score;
      r.q = q;
      r.pos_err_m = ep.norm();
      r.rot_err_rad = er.norm();
    }
    if (ep.norm() < o.tol_pos_m && er.norm() < o.tol_rot_rad) {
      r.converged = true;
      break;
    }
    mj_jacSite(m, d, jacp.data(), jacr.data(), arm.palm_site);
    Eigen::Matrix<double, 6, n> J;
    for (int i = 0; i < n; ++i) {
      for (int k = 0; k < 3; ++k) {
        J(k, i) = jacp[k * m->nv + arm.dof[i]];
        J(3 + k, i) = o.rot_weight_m * jacr[k * m->nv + arm.dof[i]];
      }
    }
    Eigen::Matrix<double, 6, 1> e;
    e << ep, o.rot_weight_m * er;
    const Eigen::Matrix<double, 6, 6> A =
        J * J.transpose() + o.damping * o.damping * Eigen::Matrix<double, 6, 6>::Identity();
    const Eigen::Matrix<double, n, 6> Jpinv =
        J.transpose() * A.ldlt().solve(Eigen::Matrix<double, 6, 6>::Identity());
    Eigen::Matrix<double, n, 1> dq = Jpinv * e;
    // null space: toward the rest pose without disturbing the palm
    const Eigen::Matrix<double, n, n> N = Eigen::Matrix<double, n, n>::Identity() - Jpinv * J;
    dq += N * (o.rest_pull * (rest - q));
    // at most 0.3 rad per joint per iteration
    const double big = dq.cwiseAbs().maxCoeff();
    if (big > 0.3) dq *= 0.3 / big;
    q = arm.Clamp(q + dq);
  }
  arm.Set(d, r.q);
  mj_kinematics(m, d);
  return r;
}

int ArmContacts(const mjModel* m, mjData* d, const ArmChain& arm, const Eigen::VectorXd& q,
                int ignore_body, double tolerance_m) {
  arm.Set(d, q);
  mj_kinematics(m, d);
  return ArmCollider(m, arm).Count(d, {ignore_body}, tolerance_m);
}

PalmPose SideGraspPose(const Eigen::Vector3d& centre, double standoff_m, double yaw_rad, bool right,
                       double behind_m) {
  // yaw 0: fingers +x, thumb up, the palm on the object's -y side (right hand) or +y side
  // (left hand) facing it; the hand frame is the same matrix for both (the left hand's palm
  // faces its frame's -y)
  Eigen::Matrix3d base;
  base.col(0) = Eigen::Vector3d::UnitZ();
  base.col(1) = Eigen::Vector3d::UnitY();
  base.col(2) = -Eigen::Vector3d::UnitX();
  const Eigen::Matrix3d turn = Eigen::AngleAxisd(yaw_rad, Eigen::Vector3d::UnitZ()).matrix();
  PalmPose pose;
  pose.rot = turn * base;
  pose.pos = centre + turn * Eigen::Vector3d(-behind_m, right ? -standoff_m : standoff_m, 0);
  return pose;
}

PalmPose TopGraspPose(const Eigen::Vector3d& top, double standoff_m, double yaw_rad, bool right,
                      double behind_m) {
  const Eigen::Vector3d f(std::cos(yaw_rad), std::sin(yaw_rad), 0);
  PalmPose pose;
  pose.rot.col(2) = -f;  // fingertips to wrist
  pose.rot.col(1) = Eigen::Vector3d(0, 0, right ? -1.0 : 1.0);
  pose.rot.col(0) = pose.rot.col(1).cross(pose.rot.col(2));
  pose.pos = top + standoff_m * Eigen::Vector3d::UnitZ() - behind_m * f;
  return pose;
}

}  // namespace simhuman::control::manip
