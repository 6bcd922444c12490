#include "simhuman/control/policy/policy_controller.h"

#include <algorithm>
#include <cmath>

#include "simhuman/control/policy/policy_net.h"
#include "simhuman/control/policy/route_steer.h"
#include "simhuman/core/geometry.h"

namespace simhuman::control {

struct WalkPolicyController::Impl {
  const world::SimWorld* world = nullptr;
  WalkIndex ix;
  WalkParams params;
  WalkState state;
  LoadedPolicy policy;
  bool fixed_target = false;
  bool has_target = false;
  std::array<double, kWalkActDim> ctrl{};
  bool started = false;
  // navigation: the route to the current stand point and where it leads
  bool navigate = true;
  NavConfig nav;
  RouteFollower follower;
  Eigen::Vector2d route_goal = Eigen::Vector2d::Constant(1e9);
  std::string route_error;
  // facing far from the route's way (a start facing elsewhere, a sharp corner): turn on the spot
  // first, as a person does (walking off in a wide arc swung the hands into a table's edge);
  // turn to the walk point's heading close to it
  RouteSteer steer;
  // leaving a cramped start (stood up between a chair and a table): a short step, heading kept,
  // to the first point of the route with room to turn
  bool exiting = false;
  Eigen::Vector2d exit_point = Eigen::Vector2d::Zero();
  double exit_yaw_rad = 0;

  // starts an exit step when `here` is cramped and the route leaves the cramped spot
  void PlanExit(const Observation& obs, const Eigen::Vector2d& here);

  // the target the policy steers to this step: the stand point, or the carrot on the route
  void SteerTo(const Observation& obs);
};

void WalkPolicyController::Impl::PlanExit(const Observation& obs, const Eigen::Vector2d& here) {
  exiting = false;
  const core::SceneCatalog& scene = obs.world->catalog();
  if (follower.empty()) return;
  const std::vector<Eigen::Vector2d>& pts = follower.path().points;
  // a route that leaves behind or beside the walker turns on the spot first: that needs more
  // room (a foot swung round caught a bed's edge, stood up in front of it)
  Eigen::Vector3d pos;
  double yaw = 0;
  PelvisPose(obs.data, ix, &pos, &yaw);
  const Eigen::Vector2d way = follower.PointAhead(kTurnProbeM) - here;
  const bool turn_first =
      way.norm() > 1e-6 &&
      std::abs(core::WrapAngle(std::atan2(way.y(), way.x()) - yaw)) > kTurnFirstRad;
  const double need = turn_first ? kTurnRoomM : kExitRoomM;
  if (PointClearance(scene, here, nav) >= need) return;
  double travelled = 0;
  for (size_t k = 1; k < pts.size() && travelled < kMaxExitM; ++k) {
    const Eigen::Vector2d a = pts[k - 1], b = pts[k];
    const double len = (b - a).norm();
    for (double u = 0; u < len && travelled + u < kMaxExitM; u += kExitProbeM) {
      const Eigen::Vector2d p = a + (b - a) * (u / len);
      if (PointClearance(scene, p, nav) < need) continue;
      exit_yaw_rad = yaw;
      exit_point = p;
      exiting = true;
      return;
    }
    travelled += len;
  }
}

void WalkPolicyController::Impl::SteerTo(const Observation& obs) {
  const Eigen::Vector2d goal = obs.task->walk_point.head<2>();
  const double goal_yaw = obs.task->walk_yaw_rad;
  const mjtNum* pelvis = obs.data->xpos + 3 * ix.agent.pelvis_body;
  const Eigen::Vector2d here(pelvis[0], pelvis[1]);
  has_target = true;
  if ((goal - route_goal).norm() > 0.05) {
    follower = RouteFollower();
    steer.final_turn = false;
  }
  route_goal = goal;
  // without navigation (or a route): straight at the walk point
  RouteFollower::Carrot carrot;
  carrot.final = true;
  if (navigate) {
    carrot.final = false;
    bool replan = follower.empty();
    if (!replan) {
      carrot = follower.Update(here);
      // pushed off the route: plan again from here
      replan = carrot.off_route_m > kReplanOffRouteM;
    }
    if (replan) {
      auto path = PlanRoute(obs.world->catalog(), here, goal, nav);
      if (path.ok()) {
        route_error.clear();
        follower = RouteFollower(*std::move(path), kRouteLookaheadM);
        carrot = follower.Update(here);
        PlanExit(obs, here);
      } else {
        // no route (e.g. a huge scene): steer straight at the walk point
        route_error = std::string(path.status().message());
        follower = RouteFollower();
        carrot.final = true;
      }
    }
    // the exit step ends within kExitDoneM of its point, or standing within the policy's start
    // radius of it (the policy takes no step for that: it would stand there for good)
    const double to_exit = (here - exit_point).norm();
    if (exiting && to_exit > kExitDoneM && (state.stepping || to_exit > params.start_radius_m)) {
      state.target_xy = exit_point;
      state.target_yaw_rad = exit_yaw_rad;
      return;
    }
    exiting = false;
    if (!carrot.final) {
      carrot.point =
          ClearCarrot(obs.world->catalog(), nav, follower, here, carrot.point, kRouteLookaheadM);
      carrot.point = SlowForTurn(follower, here, carrot.point, kRouteLookaheadM);
    }
  }
  Eigen::Vector3d pos;
  double yaw;
  PelvisPose(obs.data, ix, &pos, &yaw);
  steer.Steer(here, yaw, carrot, goal, goal_yaw, &state);
}

WalkPolicyController::WalkPolicyController(std::unique_ptr<Impl> impl) : impl_(std::move(impl)) {}
WalkPolicyController::~WalkPolicyController() = default;

core::StatusOr<std::unique_ptr<WalkPolicyController>> WalkPolicyController::Load(
    const std::string& path, const world::SimWorld* world, int agent) {
  auto impl = std::make_unique<Impl>();
  SH_ASSIGN_OR_RETURN(impl->policy, LoadPolicyFile(path));
  const PolicyMeta& meta = impl->policy.meta;
  if (meta.task != "walk" || meta.obs_dim != kWalkObsDim || meta.act_dim != kWalkActDim) {
    return absl::InvalidArgumentError(
        path + ": a '" + meta.task + "' policy with " + std::to_string(meta.obs_dim) +
        " observations and " + std::to_string(meta.act_dim) +
        " actions; the walking skill needs task 'walk' with " + std::to_string(kWalkObsDim) +
        " and " + std::to_string(kWalkActDim));
  }
  auto gait = WalkGait(meta.variant);
  if (!gait.ok()) return core::Annotate(gait.status(), path);
  impl->params = *gait;
  impl->world = world;
  SH_ASSIGN_OR_RETURN(impl->ix, MakeWalkIndex(*world, agent));
  GetHinges(world->data(), impl->ix.agent, impl->ctrl.data());
  return std::unique_ptr<WalkPolicyController>(new WalkPolicyController(std::move(impl)));
}

void WalkPolicyController::SetTarget(double x, double y, double yaw_rad) {
  impl_->fixed_target = true;
  impl_->has_target = true;
  impl_->state.target_xy = Eigen::Vector2d(x, y);
  impl_->state.target_yaw_rad = yaw_rad;
}

void WalkPolicyController::Restart() {
  Eigen::Vector2d t = impl_->state.target_xy;
  double yaw = impl_->state.target_yaw_rad;
  impl_->state = WalkState();
  impl_->state.target_xy = t;
  impl_->state.target_yaw_rad = yaw;
  impl_->started = false;
  impl_->follower = RouteFollower();
  impl_->route_goal = Eigen::Vector2d::Constant(1e9);
  impl_->steer.final_turn = false;
  impl_->exiting = false;
}

void WalkPolicyController::set_navigation(bool on) { impl_->navigate = on; }

const NavPath* WalkPolicyController::route() const {
  return impl_->follower.empty() ? nullptr : &impl_->follower.path();
}

const WalkState& WalkPolicyController::state() const { return impl_->state; }

absl::Status WalkPolicyController::Act(const Observation& obs) {
  Impl& m = *impl_;
  if (!m.fixed_target && obs.task && obs.task->get_close) m.SteerTo(obs);
  if (!m.has_target) {
    return absl::FailedPreconditionError("walk policy: step " + std::to_string(obs.step_index) +
                                         " is not a get-close step and no target was set");
  }
  UpdateWalkCommand(m.params, obs.data, m.ix, &m.state);
  std::array<float, kWalkObsDim> o;
  WalkObservation(m.params, obs.data, m.ix, m.state, o.data());
  for (float v : o) {
    if (!std::isfinite(v)) return absl::InternalError("walk policy: non-finite observation");
  }
  std::array<float, kWalkActDim> act;
  try {
    torch::NoGradGuard ng;
    torch::Tensor x = torch::from_blob(o.data(), {1, kWalkObsDim}, torch::kFloat32);
    torch::Tensor a = m.policy.actor->forward(m.policy.norm.Normalize(x)).contiguous();
    std::copy(a.data_ptr<float>(), a.data_ptr<float>() + kWalkActDim, act.begin());
  } catch (const c10::Error& e) {
    return absl::InternalError(std::string("walk policy inference: ") + e.what_without_backtrace());
  }
  WalkTargets(m.params, m.ix, m.state, act.data(), m.ctrl.data());
  for (int j = 0; j < kWalkActDim; ++j) {
    m.state.prev_action[j] = std::clamp(act[j], static_cast<float>(-kWalkActionClip),
                                        static_cast<float>(kWalkActionClip));
  }
  m.started = true;
  return absl::OkStatus();
}

void WalkPolicyController::Targets(double, core::Span<double> ctrl) const {
  SH_CHECK(ctrl.size() >= static_cast<int>(impl_->ctrl.size()),
           "a walking agent has the humanoid body's actuators first");
  std::copy(impl_->ctrl.begin(), impl_->ctrl.end(), ctrl.data());
}

bool WalkPolicyController::Arrived(const mjData* d, const WalkTolerance& tol) const {
  const Impl& m = *impl_;
  double dist, yaw_err;
  WalkErrors(d, m.ix, m.state, &dist, &yaw_err);
  const mjtNum* v = d->qvel + m.ix.agent.root_qvel;
  double speed = std::hypot(v[0], v[1]);
  return m.started && !m.state.stepping && m.state.amplitude < 0.1 && dist < tol.radius_m &&
         std::abs(yaw_err) < tol.yaw_rad && speed < tol.speed_mps;
}

bool ThighsDown(core::Span<const Eigen::Vector3d> pts, double scale) {
  if (pts.size() < core::kNumBodyJoints) return true;  // no body points: judge by height alone
  auto drop = [&](core::BodyJoint hip, core::BodyJoint knee) {
    return pts[static_cast<int>(hip)].z() - pts[static_cast<int>(knee)].z();
  };
  const double mean = 0.5 * (drop(core::BodyJoint::kLeftHip, core::BodyJoint::kLeftKnee) +
                             drop(core::BodyJoint::kRightHip, core::BodyJoint::kRightKnee));
  return mean > kThighsDownM * scale;
}

absl::Status WalkThenContactController::Act(const Observation& obs) {
  const world::AgentIndex& agent = obs.world->agent(obs.agent);
  const mjtNum* pelvis = obs.data->xpos + 3 * agent.pelvis_body;
  // standing: the pelvis high and the thighs hanging down from the hips (on a high stool the
  // pelvis is as high, with the thighs near level)
  const bool standing = pelvis[2] > 0.8 * agent.scale && ThighsDown(obs.body_points, agent.scale);
  // stood up: pelvis near standing height, trunk upright, not moving (a human half-way out of
  // a seat, leaning forward, is not the walker's to take)
  const mjtNum* v = obs.data->qvel + agent.root_qvel;
  const bool stood_still = pelvis[2] > 0.9 * world::kPelvisStandHeight * agent.scale &&
                           obs.data->xmat[9 * agent.torso_body + 8] > std::cos(kStoodTiltRad) &&
                           std::hypot(v[0], v[1]) < 0.3;
  const bool get_close = obs.task && obs.task->get_close && obs.task->posture == Posture::kStand;
  if (obs.step_index != step_) {
    step_ = obs.step_index;
    stood_since_s_ = -1;
    // walk get-close steps that start standing; "stand up" from a seat or bed is the contact
    // controller's until the human stands (below)
    if (get_close && standing) {
      walking_ = true;
      finishing_ = false;
      walker_->Restart();
    } else if (walking_) {
      // the plan moved on (its get-close test is looser); keep walking to the stand point
      // until stopped there, so the contact controller never takes over a moving human
      finishing_ = true;
      finish_deadline_s_ = obs.time_s + kMaxFinishS;
    }
  }
  // a get-close step that began seated: once the human has stood for kStoodS and is still
  // away from the walk point, walk the rest of the way
  if (get_close && !walking_) {
    if (!stood_still) {
      stood_since_s_ = -1;
    } else if (stood_since_s_ < 0) {
      stood_since_s_ = obs.time_s;
    } else if (obs.time_s - stood_since_s_ >= kStoodS) {
      Eigen::Vector2d to = obs.task->walk_point.head<2>() - Eigen::Vector2d(pelvis[0], pelvis[1]);
      if (to.norm() > kWalkAfterStandM) {
        walking_ = true;
        finishing_ = false;
        walker_->Restart();
      }
    }
  }
  if (finishing_ && (walker_->Arrived(obs.data) || obs.time_s > finish_deadline_s_)) {
    walking_ = finishing_ = false;
  }
  return active()->Act(obs);
}

void WalkThenContactController::Targets(double time_s, core::Span<double> ctrl) const {
  active()->Targets(time_s, ctrl);
}

}  // namespace simhuman::control
