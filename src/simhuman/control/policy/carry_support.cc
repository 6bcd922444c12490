#include "simhuman/control/policy/carry_support.h"

#include <Eigen/Dense>
#include <algorithm>
#include <vector>

namespace simhuman::control {
namespace {

constexpr int kAnklePitch[2] = {19, 26};  // right, left (actuator order, as carry_task.cc)

// the sum of the contact forces bodies other than the human and the floor put on the human
Eigen::Vector3d LoadOnHuman(const mjModel* m, const mjData* d, const CarryIndex& ix) {
  std::vector<bool> human(m->nbody, false);
  for (int b : ix.walk.agent.bodies) human[b] = true;
  const int floor_body = m->geom_bodyid[ix.walk.floor_geom];
  Eigen::Vector3d load = Eigen::Vector3d::Zero();
  for (int c = 0; c < d->ncon; ++c) {
    const mjContact& con = d->contact[c];
    const int b1 = m->geom_bodyid[con.geom1], b2 = m->geom_bodyid[con.geom2];
    if (human[b1] == human[b2]) continue;  // inside the human, or between two other bodies
    if ((human[b1] ? b2 : b1) == floor_body) continue;
    mjtNum f6[6];
    mj_contactForce(m, d, c, f6);
    // the frame's rows are the contact's axes; the force acts on geom2, minus it on geom1
    Eigen::Vector3d f = Eigen::Vector3d::Zero();
    for (int k = 0; k < 3; ++k) {
      f += f6[k] * Eigen::Vector3d(con.frame[3 * k], con.frame[3 * k + 1], con.frame[3 * k + 2]);
    }
    load += human[b1] ? Eigen::Vector3d(-f) : f;
  }
  return load;
}

}  // namespace

void StaticSupportTorques(const mjModel* m, const mjData* d, const CarryIndex& ix, double* tau) {
  const world::AgentIndex& a = ix.walk.agent;
  const int nv = m->nv;
  Eigen::VectorXd f = Eigen::Map<const Eigen::VectorXd>(d->qfrc_bias, nv);
  std::vector<mjtNum> jacp(3 * nv), jacr(3 * nv);
  const Eigen::Vector3d load = LoadOnHuman(m, d, ix);
  for (int site : {ix.left_hand_site, ix.right_hand_site}) {
    mj_jacSite(m, d, jacp.data(), nullptr, site);
    for (int i = 0; i < nv; ++i) {
      f[i] -= 0.5 * (jacp[i] * load.x() + jacp[nv + i] * load.y() + jacp[2 * nv + i] * load.z());
    }
  }
  // the feet: wrenches W (force, torque at each foot geom's centre) with B W = f on the root
  const int feet[2] = {ix.walk.left_foot_geom, ix.walk.right_foot_geom};
  bool on_floor[2] = {false, false};
  for (int c = 0; c < d->ncon; ++c) {
    const int g1 = d->contact[c].geom1, g2 = d->contact[c].geom2;
    for (int s = 0; s < 2; ++s) {
      on_floor[s] = on_floor[s] || (g1 == feet[s] && g2 == ix.walk.floor_geom) ||
                    (g2 == feet[s] && g1 == ix.walk.floor_geom);
    }
  }
  if (!on_floor[0] && !on_floor[1]) on_floor[0] = on_floor[1] = true;
  Eigen::MatrixXd B(6, 12);
  Eigen::VectorXd sinv(12);
  std::vector<Eigen::MatrixXd> jf(2, Eigen::MatrixXd(6, nv));
  for (int s = 0; s < 2; ++s) {
    mj_jac(m, d, jacp.data(), jacr.data(), d->geom_xpos + 3 * feet[s], m->geom_bodyid[feet[s]]);
    for (int r = 0; r < 3; ++r) {
      for (int i = 0; i < nv; ++i) {
        jf[s](r, i) = jacp[r * nv + i];
        jf[s](3 + r, i) = jacr[r * nv + i];
      }
    }
    for (int r = 0; r < 6; ++r) {
      for (int k = 0; k < 6; ++k) B(k, 6 * s + r) = jf[s](r, a.root_qvel + k);
      sinv[6 * s + r] = on_floor[s] ? (r < 3 ? 1.0 : 0.04) : 0.0;  // 0.04 = (0.2 m)^2
    }
  }
  const Eigen::VectorXd b = f.segment<6>(a.root_qvel);
  const Eigen::MatrixXd bs = B * sinv.asDiagonal();
  const Eigen::MatrixXd gram = bs * B.transpose() + 1e-9 * Eigen::MatrixXd::Identity(6, 6);
  const Eigen::VectorXd W = sinv.asDiagonal() * B.transpose() * gram.ldlt().solve(b);
  for (int j = 0; j < kWalkActDim; ++j) {
    const int v = a.hinge_qvel[j];
    double t = f[v];
    for (int s = 0; s < 2; ++s) t -= jf[s].col(v).dot(W.segment<6>(6 * s));
    tau[j] = t;
  }
}

void AddSupportToTargets(const mjModel* m, const CarryIndex& ix, const double* tau,
                         double* ctrl28) {
  for (int j = 0; j < kWalkActDim; ++j) {
    const int act = ix.walk.agent.actuator[j];
    const double kp = m->actuator_gainprm[mjNGAIN * act];
    if (kp <= 0) continue;
    ctrl28[j] = std::clamp(ctrl28[j] + tau[j] / kp, ix.walk.ctrl_lo[j], ix.walk.ctrl_hi[j]);
  }
}

void BalanceAnkles(const mjModel* m, mjData* d, const CarryIndex& ix, double gain, double damping_s,
                   double* ctrl28) {
  const world::AgentIndex& a = ix.walk.agent;
  mj_subtreeVel(m, d);
  const int root = a.pelvis_body;
  const Eigen::Vector3d com(d->subtree_com + 3 * root), vel(d->subtree_linvel + 3 * root);
  const Eigen::Vector2d mid = 0.5 * (Eigen::Vector2d(d->geom_xpos + 3 * ix.walk.left_foot_geom) +
                                     Eigen::Vector2d(d->geom_xpos + 3 * ix.walk.right_foot_geom));
  const Eigen::Vector2d err = com.head<2>() - mid + damping_s * vel.head<2>();
  for (int j : kAnklePitch) {
    const int jnt = m->dof_jntid[a.hinge_qvel[j]];
    const Eigen::Vector3d axis(d->xaxis + 3 * jnt), anchor(d->xanchor + 3 * jnt);
    // the foot held flat, turning the ankle by dq turns the body about it by -dq
    const Eigen::Vector2d per_rad = (-axis.cross(com - anchor)).head<2>();
    const double n2 = per_rad.squaredNorm();
    if (n2 < 1e-6) continue;
    const double dq = -gain * err.dot(per_rad) / n2;
    ctrl28[j] = std::clamp(ctrl28[j] + dq, ix.walk.ctrl_lo[j], ix.walk.ctrl_hi[j]);
  }
}

}  // namespace simhuman::control
