#include "simhuman/learn/walk_env.h"

#include <algorithm>
#include <cmath>

#include "simhuman/core/geometry.h"
#include "simhuman/learn/amp_features.h"
#include "simhuman/learn/motion_clip.h"

namespace simhuman::learn {
namespace {

using control::kWalkActDim;

constexpr double kDeg = M_PI / 180.0;
constexpr double kSuccessRadius = 0.2, kSuccessYaw = 15 * kDeg, kStoppedSpeed = 0.2;
constexpr int kSuccessHold = 15;     // policy steps (0.5 s)
constexpr int kNextTargetHold = 45;  // 1.5 s, then a new target
constexpr int kFirstLegJoint = 14;

}  // namespace

core::StatusOr<std::unique_ptr<WalkTask>> WalkTask::Create(int num_envs, WalkPhysicsSolver solver,
                                                           const std::vector<double>& body_scales,
                                                           const std::string& gait,
                                                           const WalkRewardWeights& weights) {
  if (num_envs <= 0) return absl::InvalidArgumentError("walk task: --envs must be positive");
  if (body_scales.empty()) return absl::InvalidArgumentError("walk task: no body scales");
  std::unique_ptr<WalkTask> t(new WalkTask());
  SH_ASSIGN_OR_RETURN(t->params_, control::WalkGait(gait));
  t->w_ = weights;
  world::ModelOptions opt;
  opt.timestep_s = control::kWalkPhysicsDt;
  opt.solver = solver == WalkPhysicsSolver::kPgs ? "pgs" : "newton";
  for (double scale : body_scales) {
    if (!(scale >= 0.5 && scale <= 1.5)) {
      return absl::InvalidArgumentError("walk task: body scale " + std::to_string(scale) +
                                        " is outside [0.5, 1.5]");
    }
    world::AgentSpec spec;
    spec.scale = scale;
    SH_ASSIGN_OR_RETURN(auto w, world::SimWorld::Create(core::SceneCatalog(), {spec}, opt));
    SH_ASSIGN_OR_RETURN(control::WalkIndex ix, control::MakeWalkIndex(*w, 0));
    // one human on a floor: small arenas keep E copies of mjData cheap to allocate and reset
    mjModel* m = w->mutable_model();
    m->nconmax = 64;
    m->njmax = 400;
    m->nstack = 150000;
    t->worlds_.push_back(std::move(w));
    t->ixs_.push_back(ix);
  }
  // every scale has the same bodies (ids), so one table serves all
  const mjModel* m0 = t->worlds_[0]->model();
  t->foot_body_.assign(m0->nbody, 0);
  t->foot_body_[t->ixs_[0].agent.left_foot_body] = 1;
  t->foot_body_[t->ixs_[0].agent.right_foot_body] = 1;
  t->envs_.resize(num_envs);
  for (int i = 0; i < num_envs; ++i) {
    Env& e = t->envs_[i];
    e.w = i % static_cast<int>(t->worlds_.size());
    e.d = mj_makeData(t->worlds_[e.w]->model());
  }
  return t;
}

WalkTask::~WalkTask() {
  for (Env& e : envs_) {
    if (e.d) mj_deleteData(e.d);
  }
}

void WalkTask::DrawTarget(Env& e) {
  const control::WalkIndex& ix = ixs_[e.w];
  const double L = control::WalkScaleOf(ix).length;  // targets in the adult's metres, times s
  Eigen::Vector3d pos;
  double yaw;
  control::PelvisPose(e.d, ix, &pos, &yaw);
  double a = (45.0 + 135.0 * std::clamp(curriculum_, 0.0, 1.0)) * kDeg;
  e.route = control::RouteFollower();
  e.route_final = false;
  if (route_share_ > 0 && e.rng.Uniform() < route_share_) {
    DrawRoute(e, pos.head<2>(), yaw);
    return;
  }
  if (e.rng.Uniform() < 0.2) {
    // a short step in any direction keeping the heading (steps back and sideways)
    double dist = e.rng.Uniform(0.3, std::max(0.5, params_.short_step_m));
    double bearing = yaw + e.rng.Uniform(-M_PI, M_PI);
    e.s.target_xy =
        pos.head<2>() + L * dist * Eigen::Vector2d(std::cos(bearing), std::sin(bearing));
    e.s.target_yaw_rad = core::WrapAngle(yaw + e.rng.Uniform(-0.3, 0.3));
    e.hold = 0;
    return;
  }
  double dist =
      e.rng.Uniform() < 0.1 ? e.rng.Uniform(0.0, 0.3) : 0.3 + 9.7 * std::pow(e.rng.Uniform(), 1.5);
  double bearing = yaw + e.rng.Uniform(-a, a);
  e.s.target_xy = pos.head<2>() + L * dist * Eigen::Vector2d(std::cos(bearing), std::sin(bearing));
  e.s.target_yaw_rad = core::WrapAngle(bearing + e.rng.Uniform(-a, a));
  e.hold = 0;
}

void WalkTask::DrawRoute(Env& e, const Eigen::Vector2d& from, double yaw) {
  const double L = control::WalkScaleOf(ixs_[e.w]).length;
  control::NavPath path;
  path.points.push_back(from);
  double heading = yaw + e.rng.Uniform(-M_PI, M_PI);
  const int legs = e.rng.UniformInt(2, 3);
  for (int k = 0; k < legs; ++k) {
    const double len = L * e.rng.Uniform(1.0, 3.0);
    path.points.push_back(path.points.back() +
                          len * Eigen::Vector2d(std::cos(heading), std::sin(heading)));
    path.length_m += len;
    heading += e.rng.Uniform(-125.0, 125.0) * kDeg;
  }
  e.goal = path.points.back();
  e.goal_yaw = core::WrapAngle(e.rng.Uniform(-M_PI, M_PI));
  e.route = control::RouteFollower(std::move(path), control::kRouteLookaheadM);
  e.steer = control::RouteSteer();
  e.hold = 0;
  SteerRoute(e);
}

void WalkTask::SteerRoute(Env& e) {
  if (e.route.empty()) return;
  Eigen::Vector3d pos;
  double yaw;
  control::PelvisPose(e.d, ixs_[e.w], &pos, &yaw);
  control::RouteFollower::Carrot carrot = e.route.Update(pos.head<2>());
  if (!carrot.final) {
    carrot.point =
        control::SlowForTurn(e.route, pos.head<2>(), carrot.point, control::kRouteLookaheadM);
  }
  e.route_final = carrot.final;
  e.steer.Steer(pos.head<2>(), yaw, carrot, e.goal, e.goal_yaw, &e.s);
}

void WalkTask::SetTarget(int i, double x, double y, double yaw_rad) {
  envs_[i].s.target_xy = Eigen::Vector2d(x, y);
  envs_[i].s.target_yaw_rad = yaw_rad;
  envs_[i].hold = 0;
  envs_[i].route = control::RouteFollower();
}

void WalkTask::Reset(int i, uint64_t seed, float* obs) {
  Env& e = envs_[i];
  const mjModel* m = worlds_[e.w]->model();
  const control::WalkIndex& ix = ixs_[e.w];
  e.rng = core::Rng(seed);
  mjData* d = e.d;
  mj_resetData(m, d);
  const world::AgentIndex& a = ix.agent;
  double yaw = e.rng.Uniform(-M_PI, M_PI);
  d->qpos[a.root_qpos + 0] = 0;
  d->qpos[a.root_qpos + 1] = 0;
  d->qpos[a.root_qpos + 3] = std::cos(yaw / 2);
  d->qpos[a.root_qpos + 4] = 0;
  d->qpos[a.root_qpos + 5] = 0;
  d->qpos[a.root_qpos + 6] = std::sin(yaw / 2);
  const auto& nominal = control::WalkNominalPose();
  for (int j = 0; j < kWalkActDim; ++j) {
    double q = std::clamp(nominal[j] + e.rng.Normal(0.03), ix.ctrl_lo[j], ix.ctrl_hi[j]);
    d->qpos[a.hinge_qpos[j]] = q;
    d->ctrl[a.actuator[j]] = q;
  }
  // put the lowest foot corner on the floor
  mj_forward(m, d);
  const double lowest = LowestBoxCornerZ(m, d, {ix.left_foot_geom, ix.right_foot_geom});
  d->qpos[a.root_qpos + 2] -= lowest - 0.001;
  mj_forward(m, d);
  e.s = control::WalkState();
  e.s.phase = e.rng.Uniform();
  e.steps = 0;
  e.success = false;
  DrawTarget(e);
  control::UpdateWalkCommand(params_, d, ix, &e.s);
  control::WalkObservation(params_, d, ix, e.s, obs);
}

int WalkTask::amp_feature_dim() const { return kAmpFeatureDim; }

void WalkTask::AmpFeatures(int i, float* out) {
  const mjModel* m = worlds_[envs_[i].w]->model();
  mj_kinematics(m, envs_[i].d);
  learn::AmpFeatures(m, envs_[i].d, ixs_[envs_[i].w].agent, out);
}

core::StatusOr<std::vector<float>> WalkTask::AmpClipFeatures(const MotionClip& clip) const {
  SH_ASSIGN_OR_RETURN(MotionClip at_rate, ResampleClip(clip, 1.0 / control::kWalkPolicyDt));
  return ClipAmpFeatures(worlds_[0]->model(), ixs_[0].agent, at_rate);
}

bool WalkTask::Fallen(int i) const {
  const mjModel* m = worlds_[envs_[i].w]->model();
  const mjData* d = envs_[i].d;
  const control::WalkIndex& ix = ixs_[envs_[i].w];
  const world::AgentIndex& a = ix.agent;
  const double L = control::WalkScaleOf(ix).length;
  if (d->xpos[3 * a.pelvis_body + 2] < 0.55 * L || d->xpos[3 * a.head_body + 2] < 0.8 * L) {
    return true;
  }
  if (d->xmat[9 * a.torso_body + 8] < std::cos(70 * kDeg)) return true;
  for (int c = 0; c < d->ncon; ++c) {
    int g1 = d->contact[c].geom1, g2 = d->contact[c].geom2;
    int other = g1 == ix.floor_geom ? g2 : (g2 == ix.floor_geom ? g1 : -1);
    if (other >= 0 && !foot_body_[m->geom_bodyid[other]]) return true;
  }
  return false;
}

void WalkTask::Step(int i, const float* action, float* obs, StepInfo* info) {
  Env& e = envs_[i];
  const mjModel* m = worlds_[e.w]->model();
  const control::WalkIndex& ix = ixs_[e.w];
  // velocities and heights in the adult's units (control::WalkScale)
  const control::WalkScale fr = control::WalkScaleOf(ix);
  const double speed_unit = fr.length / fr.time;
  mjData* d = e.d;
  const world::AgentIndex& a = ix.agent;
  double ctrl[kWalkActDim];
  control::WalkTargets(params_, ix, e.s, action, ctrl);
  double power = 0;
  for (int k = 0; k < control::kWalkSubsteps; ++k) {
    for (int j = 0; j < kWalkActDim; ++j) d->ctrl[a.actuator[j]] = ctrl[j];
    mj_step(m, d);
    for (int j = 0; j < kWalkActDim; ++j) {
      power += std::abs(d->actuator_force[a.actuator[j]] * d->qvel[a.hinge_qvel[j]]);
    }
  }
  power /= control::kWalkSubsteps;
  ++e.steps;
  bool finite = world::AllFinite(d->qpos, m->nq) && world::AllFinite(d->qvel, m->nv);
  if (!finite) {
    std::fill(obs, obs + control::kWalkObsDim, 0.f);
    *info = StepInfo{0.f, true, false, e.success};
    return;
  }

  // reward for the command and gait phase this action was taken under
  WalkRewardTerms& t = e.terms;
  Eigen::Vector3d pos;
  double yaw;
  control::PelvisPose(d, ix, &pos, &yaw);
  const mjtNum* v = d->qvel + a.root_qvel;
  double c = std::cos(yaw), s = std::sin(yaw);
  double vx = (c * v[0] + s * v[1]) / speed_unit, vy = (-s * v[0] + c * v[1]) / speed_unit;
  const mjtNum* R = d->xmat + 9 * a.pelvis_body;
  double wz = (R[6] * v[3] + R[7] * v[4] + R[8] * v[5]) * fr.time;
  t.velocity = std::exp(
      -((vx - e.s.cmd.vx) * (vx - e.s.cmd.vx) + (vy - e.s.cmd.vy) * (vy - e.s.cmd.vy)) / 0.25);
  t.yaw_rate = std::exp(-(wz - e.s.cmd.yaw_rate) * (wz - e.s.cmd.yaw_rate) / 0.5);
  // progress along the commanded direction (a gradient where velocity tracking has none)
  double cmd_speed = std::hypot(e.s.cmd.vx, e.s.cmd.vy);
  t.progress = cmd_speed > 0.05
                   ? std::clamp((vx * e.s.cmd.vx + vy * e.s.cmd.vy) / cmd_speed, -0.5, cmd_speed)
                   : 0.0;
  t.facing = 0.5 * (1.0 + std::cos(e.s.facing_rad - yaw));
  double ref[kWalkActDim];
  control::WalkReference(params_, e.s.phase, e.s.amplitude, e.s.cmd, ref);
  double err_legs = 0, err_upper = 0;
  for (int j = 0; j < kWalkActDim; ++j) {
    double dq = d->qpos[a.hinge_qpos[j]] - ref[j];
    (j >= kFirstLegJoint ? err_legs : err_upper) += dq * dq;
  }
  t.gait_legs = std::exp(-err_legs / w_.gait_legs_width);
  t.gait_upper = std::exp(-err_upper / 1.0);
  bool lc, rc;
  control::FootContacts(d, ix, &lc, &rc);
  // feet sliding while on the ground
  t.foot_slip = 0;
  for (int side = 0; side < 2; ++side) {
    if (!(side == 0 ? lc : rc)) continue;
    mjtNum vel[6];
    mj_objectVelocity(m, d, mjOBJ_BODY, side == 0 ? a.left_foot_body : a.right_foot_body, vel, 0);
    t.foot_slip += (vel[3] * vel[3] + vel[4] * vel[4]) / (speed_unit * speed_unit);
  }
  int el, er;
  control::WalkExpectedContacts(params_, e.s.phase, e.s.amplitude, &el, &er);
  auto match = [](int expect, bool contact) {
    return expect == 0 ? 1.0 : ((expect > 0) == contact ? 1.0 : 0.0);
  };
  t.contact = 0.5 * (match(el, lc) + match(er, rc));
  t.upright = std::max(0.0, d->xmat[9 * a.torso_body + 8]);
  // 1 - cos(20 deg) = 0.0603: each factor is 1/e at a 20 degree tilt (wide enough to pull a
  // hunched 30-40 degree posture up; a 10 degree kernel gave no gradient there)
  t.posture = std::exp(-(1.0 - d->xmat[9 * a.head_body + 8]) / 0.0603) *
              std::exp(-(1.0 - d->xmat[9 * a.torso_body + 8]) / 0.0603);
  double dh = (pos.z() / fr.length - 0.93) / 0.07;
  t.height = std::exp(-dh * dh);
  double dist = (e.s.target_xy - pos.head<2>()).norm();
  double yaw_err = core::WrapAngle(e.s.target_yaw_rad - yaw);
  double speed2 = vx * vx + vy * vy;
  // on a route, only its goal counts (not a carrot on the way)
  bool inside = dist < kSuccessRadius && std::abs(yaw_err) < kSuccessYaw &&
                (e.route.empty() || e.route_final);
  t.at_target = inside ? std::exp(-speed2 / 0.1) : 0.0;
  // action rate over the used entries (the ignored arm entries are pure exploration noise)
  double rate = 0;
  int used = 0;
  for (int j = 0; j < kWalkActDim; ++j) {
    double ac = std::clamp(static_cast<double>(action[j]), -control::kWalkActionClip,
                           control::kWalkActionClip);
    double dd = ac - e.s.prev_action[j];
    if (control::WalkActionUsed(j)) {
      rate += dd * dd;
      ++used;
    }
    e.s.prev_action[j] = static_cast<float>(ac);
  }
  t.action_rate = rate / used;
  t.power = power;
  t.total =
      w_.scale * (w_.velocity * t.velocity + w_.progress * t.progress + w_.yaw_rate * t.yaw_rate +
                  w_.facing * t.facing + w_.gait_legs * t.gait_legs + w_.gait_upper * t.gait_upper +
                  w_.contact * t.contact + w_.upright * t.upright + w_.height * t.height +
                  w_.posture * t.posture + w_.alive + w_.at_target * t.at_target -
                  w_.action_rate * t.action_rate - w_.power * t.power - w_.foot_slip * t.foot_slip);

  // success: inside the tolerances and stopped for 0.5 s; a new target after 1.5 s
  if (inside && speed2 < kStoppedSpeed * kStoppedSpeed) {
    ++e.hold;
  } else {
    e.hold = 0;
  }
  if (e.hold >= kSuccessHold) e.success = true;
  if (e.hold >= kNextTargetHold) DrawTarget(e);

  bool fell = Fallen(i);
  SteerRoute(e);
  control::UpdateWalkCommand(params_, d, ix, &e.s);
  control::WalkObservation(params_, d, ix, e.s, obs);
  info->reward = static_cast<float>(t.total);
  info->terminated = fell;
  info->truncated = e.steps >= kMaxSteps;
  info->success = e.success;
}

}  // namespace simhuman::learn
