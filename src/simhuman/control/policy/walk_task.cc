#include "simhuman/control/policy/walk_task.h"

#include <algorithm>
#include <cmath>

namespace simhuman::control {
namespace {

// actuator (hinge) order of world::HumanoidJointNames()
enum J {
  kAbdX,
  kAbdY,
  kAbdZ,
  kNeckX,
  kNeckY,
  kNeckZ,
  kRShX,
  kRShY,
  kRShZ,
  kRElbow,
  kLShX,
  kLShY,
  kLShZ,
  kLElbow,
  kRHipX,
  kRHipY,
  kRHipZ,
  kRKnee,
  kRAnkX,
  kRAnkY,
  kRAnkZ,
  kLHipX,
  kLHipY,
  kLHipZ,
  kLKnee,
  kLAnkX,
  kLAnkY,
  kLAnkZ
};

double Clamp(double x, double lo, double hi) { return std::min(hi, std::max(lo, x)); }

// world vector -> heading frame (rotate by -yaw about z)
Eigen::Vector3d ToHeading(const Eigen::Vector3d& v, double yaw) {
  double c = std::cos(yaw), s = std::sin(yaw);
  return Eigen::Vector3d(c * v.x() + s * v.y(), -s * v.x() + c * v.y(), v.z());
}

Eigen::Vector3d Vec(const mjtNum* x) { return Eigen::Vector3d(x[0], x[1], x[2]); }

}  // namespace

core::StatusOr<WalkIndex> MakeWalkIndex(const world::SimWorld& world, int a) {
  WalkIndex ix;
  const mjModel* m = world.model();
  ix.agent = world.agent(a);
  std::string p = world::AgentPrefix(a);
  ix.floor_geom = mj_name2id(m, mjOBJ_GEOM, "floor");
  ix.left_foot_geom = mj_name2id(m, mjOBJ_GEOM, (p + "left_foot_geom").c_str());
  ix.right_foot_geom = mj_name2id(m, mjOBJ_GEOM, (p + "right_foot_geom").c_str());
  if (ix.floor_geom < 0) return absl::NotFoundError("walk task: the model has no geom 'floor'");
  if (ix.left_foot_geom < 0 || ix.right_foot_geom < 0) {
    return absl::NotFoundError("walk task: humanoid '" + p + "' has no foot geoms");
  }
  for (int j = 0; j < kWalkActDim; ++j) {
    int act = ix.agent.actuator[j];
    ix.ctrl_lo[j] = m->actuator_ctrlrange[2 * act];
    ix.ctrl_hi[j] = m->actuator_ctrlrange[2 * act + 1];
  }
  return ix;
}

core::StatusOr<WalkParams> WalkGait(std::string_view name) {
  WalkParams p;
  if (name.empty()) return p;
  if (name == "human") {
    p.vmax_mps = 1.3;
    p.gait_period_s = 1.05;
    p.swing_frac = 0.40;
    p.hip_swing_rad = 0.42;
    p.knee_swing_rad = 1.0;
    p.knee_stance_rad = 0.15;
    p.knee_bend_rad = -0.13;
    return p;
  }
  return absl::InvalidArgumentError("unknown walking gait '" + std::string(name) +
                                    "'; valid: \"\" (the original), human");
}

std::vector<std::string> WalkGaitNames() { return {"", "human"}; }

const std::array<double, kWalkActDim>& WalkNominalPose() {
  static const std::array<double, kWalkActDim> q = [] {
    std::array<double, kWalkActDim> n{};
    n[kAbdY] = 0.05;
    n[kRShX] = n[kLShX] = 0.12;
    n[kRElbow] = n[kLElbow] = 0.3;
    n[kRHipY] = n[kLHipY] = 0.12;
    n[kRKnee] = n[kLKnee] = 0.25;
    n[kRAnkY] = n[kLAnkY] = -0.13;  // hip - knee: foot flat
    return n;
  }();
  return q;
}

void WalkReference(const WalkParams& p, double phase, double amplitude, const WalkCommand& cmd,
                   double* q) {
  const auto& n = WalkNominalPose();
  std::copy(n.begin(), n.end(), q);
  const double amp = Clamp(amplitude, 0.0, 1.0);
  // per-cycle excursions: sagittal hip swing for vx, lateral for vy, hip yaw for turning
  const double a_sag = p.hip_swing_rad * Clamp(cmd.vx / p.vmax_mps, -0.6, 1.0) * amp;
  const double a_lat = 0.12 * Clamp(cmd.vy / 1.0, -1.0, 1.0) * amp;  // side steps: any gait
  const double a_yaw = 0.25 * Clamp(cmd.yaw_rate / p.max_yaw_rate, -1.0, 1.0) * amp;
  for (int side = 0; side < 2; ++side) {  // 0 left, 1 right
    double psi = std::fmod(phase + 0.5 * side, 1.0);
    bool swing = psi < p.swing_frac;
    double u = swing ? psi / p.swing_frac : (psi - p.swing_frac) / (1.0 - p.swing_frac);
    double bump = std::sin(M_PI * u);
    // position of the foot along each axis goes -a -> +a in swing and back in stance
    double along = swing ? -std::cos(M_PI * u) : std::cos(M_PI * u);
    int hx = side == 0 ? kLHipX : kRHipX, hy = side == 0 ? kLHipY : kRHipY;
    int hz = side == 0 ? kLHipZ : kRHipZ, kn = side == 0 ? kLKnee : kRKnee;
    int ax = side == 0 ? kLAnkX : kRAnkX, ay = side == 0 ? kLAnkY : kRAnkY;
    int sy = side == 0 ? kLShY : kRShY;
    double sag = a_sag * along;
    double lat = a_lat * along;  // + = foot moves to the agent's left
    q[hy] += sag + (swing ? 0.35 * amp * bump : 0.0);
    q[kn] += amp * (p.knee_bend_rad + (swing ? p.knee_swing_rad : p.knee_stance_rad) * bump);
    q[ay] = q[hy] - q[kn] + (swing ? 0.3 * amp * bump : 0.0);  // flat foot (toes down in swing)
    // hip_x is abduction-positive on both sides; left abduction moves the foot to +y
    double hip_x = side == 0 ? lat : -lat;
    q[hx] += hip_x;
    q[ax] += -lat;
    q[hz] += a_yaw * along;
    // arms swing against the leg of their side
    q[sy] += -0.8 * sag;
  }
}

void WalkExpectedContacts(const WalkParams& p, double phase, double amplitude, int* left,
                          int* right) {
  for (int side = 0; side < 2; ++side) {
    int& out = side == 0 ? *left : *right;
    double psi = std::fmod(phase + 0.5 * side, 1.0);
    if (amplitude < 0.3) {
      out = 1;
    } else if (psi < p.swing_frac) {
      double u = psi / p.swing_frac;
      out = (u > 0.1 && u < 0.9) ? -1 : 0;
    } else {
      double u = (psi - p.swing_frac) / (1.0 - p.swing_frac);
      out = (u > 0.05 && u < 0.95) ? 1 : 0;
    }
  }
}

void PelvisPose(const mjData* d, const WalkIndex& ix, Eigen::Vector3d* pos, double* yaw) {
  *pos = Vec(d->xpos + 3 * ix.agent.pelvis_body);
  *yaw = world::PelvisYaw(d, ix.agent);
}

void WalkErrors(const mjData* d, const WalkIndex& ix, const WalkState& s, double* dist_m,
                double* yaw_err_rad) {
  Eigen::Vector3d pos;
  double yaw;
  PelvisPose(d, ix, &pos, &yaw);
  *dist_m = (s.target_xy - pos.head<2>()).norm();
  *yaw_err_rad = core::WrapAngle(s.target_yaw_rad - yaw);
}

void UpdateWalkCommand(const WalkParams& p, const mjData* d, const WalkIndex& ix, WalkState* s) {
  // lengths, speeds and times in the adult's units (Froude scaling, WalkScale)
  const WalkScale fr = WalkScaleOf(ix);
  Eigen::Vector3d pos;
  double yaw;
  PelvisPose(d, ix, &pos, &yaw);
  Eigen::Vector2d delta = (s->target_xy - pos.head<2>()) / fr.length;
  double dist = delta.norm();
  double yaw_err = core::WrapAngle(s->target_yaw_rad - yaw);
  if (!s->stepping && (dist > p.start_radius_m || std::abs(yaw_err) > p.start_yaw_rad)) {
    s->stepping = true;
    s->short_step = dist < p.short_step_m;
  } else if (s->stepping && dist < p.stop_radius_m && std::abs(yaw_err) < p.stop_yaw_rad) {
    s->stepping = false;
  }
  WalkCommand c;
  s->facing_rad = s->target_yaw_rad;
  if (s->stepping) {
    // face the target while far, the requested heading when close
    double bearing = std::atan2(delta.y(), delta.x());
    // a target that moved (or a human pushed) well beyond stepping range ends the short step
    if (dist > p.short_step_m + 0.5) s->short_step = false;
    double w = s->short_step
                   ? 0.0
                   : Clamp((dist - p.near_m) / std::max(1e-6, p.far_m - p.near_m), 0.0, 1.0);
    double facing = s->target_yaw_rad + w * core::WrapAngle(bearing - s->target_yaw_rad);
    s->facing_rad = facing;
    c.yaw_rate = Clamp(2.0 * core::WrapAngle(facing - yaw), -p.max_yaw_rate, p.max_yaw_rate);
    double speed = p.vmax_mps * Clamp((dist - 0.05) / 1.0, 0.0, 1.0);
    Eigen::Vector3d local = ToHeading(Eigen::Vector3d(delta.x(), delta.y(), 0), yaw);
    Eigen::Vector2d dir = Eigen::Vector2d::Zero();
    if (dist > 1e-6) dir = Eigen::Vector2d(local.x(), local.y()) / dist;
    // beyond stepping range: walk forward, turning first if the target is behind
    if (!s->short_step && dist > p.turn_first_m) speed *= 0.5 * (1.0 + dir.x());
    c.vx = speed * dir.x();
    c.vy = speed * dir.y();
    // sideways and backwards steps are slower
    c.vy = Clamp(c.vy, -0.4, 0.4);
    c.vx = std::max(c.vx, -0.4);
  }
  s->cmd = c;
  const double dt = kWalkPolicyDt / fr.time;  // the adult's time
  double target_amp = s->stepping ? 1.0 : 0.0;
  s->amplitude += (target_amp - s->amplitude) * std::min(1.0, dt / 0.25);
  s->phase = std::fmod(s->phase + dt / p.gait_period_s, 1.0);
}

void FootContacts(const mjData* d, const WalkIndex& ix, bool* left, bool* right) {
  *left = *right = false;
  for (int i = 0; i < d->ncon; ++i) {
    int g1 = d->contact[i].geom1, g2 = d->contact[i].geom2;
    if (g1 == ix.left_foot_geom || g2 == ix.left_foot_geom) *left = true;
    if (g1 == ix.right_foot_geom || g2 == ix.right_foot_geom) *right = true;
  }
}

void WalkObservation(const WalkParams& p, const mjData* d, const WalkIndex& ix, const WalkState& s,
                     float* obs) {
  (void)p;
  // in the adult's units: lengths / s, speeds / sqrt(s), rates x sqrt(s) (WalkScale)
  const WalkScale fr = WalkScaleOf(ix);
  const double speed = fr.length / fr.time, rate = 1.0 / fr.time;
  Eigen::Vector3d pos;
  double yaw;
  PelvisPose(d, ix, &pos, &yaw);
  const mjtNum* R = d->xmat + 9 * ix.agent.pelvis_body;
  Eigen::Vector3d x_axis(R[0], R[3], R[6]), z_axis(R[2], R[5], R[8]);
  const mjtNum* qv = d->qvel + ix.agent.root_qvel;
  Eigen::Vector3d lin = Vec(qv);
  // free joint angular velocity is in the body frame
  Eigen::Vector3d w_local = Vec(qv + 3);
  Eigen::Vector3d w_world(R[0] * w_local.x() + R[1] * w_local.y() + R[2] * w_local.z(),
                          R[3] * w_local.x() + R[4] * w_local.y() + R[5] * w_local.z(),
                          R[6] * w_local.x() + R[7] * w_local.y() + R[8] * w_local.z());
  int k = 0;
  auto put3 = [&](const Eigen::Vector3d& v) {
    for (int i = 0; i < 3; ++i) obs[k++] = static_cast<float>(v[i]);
  };
  obs[k++] = static_cast<float>(pos.z() / fr.length);
  put3(ToHeading(z_axis, yaw));
  put3(ToHeading(x_axis, yaw));
  put3(ToHeading(lin / speed, yaw));
  put3(ToHeading(w_world / rate, yaw));
  const auto& n = WalkNominalPose();
  for (int j = 0; j < kWalkActDim; ++j) {
    obs[k++] = static_cast<float>(d->qpos[ix.agent.hinge_qpos[j]] - n[j]);
  }
  for (int j = 0; j < kWalkActDim; ++j) {
    obs[k++] = static_cast<float>(0.1 * d->qvel[ix.agent.hinge_qvel[j]] / rate);
  }
  for (int j = 0; j < kWalkActDim; ++j) obs[k++] = s.prev_action[j];
  Eigen::Vector2d delta = (s.target_xy - pos.head<2>()) / fr.length;
  double dist = delta.norm();
  Eigen::Vector3d local = ToHeading(Eigen::Vector3d(delta.x(), delta.y(), 0), yaw);
  double clip = dist > 3.0 ? 3.0 / dist : 1.0;
  obs[k++] = static_cast<float>(local.x() * clip);
  obs[k++] = static_cast<float>(local.y() * clip);
  obs[k++] = static_cast<float>(std::min(dist, 10.0));
  double yaw_err = core::WrapAngle(s.target_yaw_rad - yaw);
  obs[k++] = static_cast<float>(std::sin(yaw_err));
  obs[k++] = static_cast<float>(std::cos(yaw_err));
  obs[k++] = static_cast<float>(s.cmd.vx);
  obs[k++] = static_cast<float>(s.cmd.vy);
  obs[k++] = static_cast<float>(s.cmd.yaw_rate);
  obs[k++] = static_cast<float>(std::sin(2 * M_PI * s.phase));
  obs[k++] = static_cast<float>(std::cos(2 * M_PI * s.phase));
  obs[k++] = static_cast<float>(s.amplitude);
  bool lc, rc;
  FootContacts(d, ix, &lc, &rc);
  obs[k++] = lc ? 1.f : 0.f;
  obs[k++] = rc ? 1.f : 0.f;
  for (int foot : {ix.agent.left_foot_body, ix.agent.right_foot_body}) {
    put3(ToHeading((Vec(d->xpos + 3 * foot) - pos) / fr.length, yaw));
  }
}

WalkScale WalkScaleOf(const WalkIndex& ix) {
  WalkScale f;
  if (ix.agent.scale > 0 && ix.agent.scale != 1.0) {
    f.length = ix.agent.scale;
    f.time = std::sqrt(ix.agent.scale);
  }
  return f;
}

bool WalkActionUsed(int j) { return j >= 0 && j < kWalkActDim && (j < kRShX || j > kLElbow); }

void WalkTargets(const WalkParams& p, const WalkIndex& ix, const WalkState& s, const float* action,
                 double* ctrl28) {
  WalkReference(p, s.phase, s.amplitude, s.cmd, ctrl28);
  for (int j = 0; j < kWalkActDim; ++j) {
    if (!WalkActionUsed(j)) continue;  // the arms follow the reference swing
    double a = Clamp(static_cast<double>(action[j]), -kWalkActionClip, kWalkActionClip);
    ctrl28[j] = Clamp(ctrl28[j] + kWalkActionScale * a, ix.ctrl_lo[j], ix.ctrl_hi[j]);
  }
}

double LowestBoxCornerZ(const mjModel* m, const mjData* d, const std::vector<int>& geoms) {
  double lowest = 1e9;
  for (int g : geoms) {
    const mjtNum* R = d->geom_xmat + 9 * g;
    const mjtNum* sz = m->geom_size + 3 * g;
    for (int c = 0; c < 8; ++c) {
      double z = d->geom_xpos[3 * g + 2];
      for (int k = 0; k < 3; ++k) z += ((c >> k) & 1 ? 1 : -1) * sz[k] * R[6 + k];
      lowest = std::min(lowest, z);
    }
  }
  return lowest;
}

}  // namespace simhuman::control
