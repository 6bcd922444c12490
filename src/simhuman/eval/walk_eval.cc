#include "simhuman/eval/walk_eval.h"

#include <algorithm>
#include <cmath>

#include "simhuman/control/policy/policy_controller.h"
#include "simhuman/control/policy/walk_task.h"
#include "simhuman/control/runner.h"
#include "simhuman/core/geometry.h"
#include "simhuman/core/rng.h"
#include "simhuman/eval/episode.h"
#include "simhuman/eval/replay.h"
#include "simhuman/world/sim_world.h"

namespace simhuman::eval {

namespace {

// the height of human 0's head point (the fall rule's point, control/runner.h)
double HeadPointZ(const world::SimWorld& world, const mjData* d) {
  std::vector<Eigen::Vector3d> pts;
  world.AllBodyPoints(d, 0, &pts);
  return pts[static_cast<int>(core::BodyJoint::kHead)].z();
}

// an episode's target pose for the walker (world frame; m, rad)
struct WalkTarget {
  double x_m = 0, y_m = 0;
  double yaw_rad = 0;
};

// model ids the per-step measures look at
struct WalkIds {
  int floor = -1;
  int left_foot = -1, right_foot = -1;  // foot geoms
  int arm_body[2][2] = {};              // {upper arm, hand} bodies, left then right
};

// running sums of an episode's per-step measures
struct WalkTally {
  int hold = 0;          // consecutive policy steps arrived
  double skate = 0;      // horizontal speeds of feet touching the floor (m/s)
  double path = 0;       // pelvis path length (m)
  long skate_n = 0;      // foot-floor contacts summed into `skate`
  double arm_raise = 0;  // the higher arm's raise (deg), per policy step
  long arm_n = 0;        // policy steps summed into `arm_raise`
};

// draws the episode's distance, bearing and target heading from `rng` (after the start yaw)
WalkTarget DrawTarget(const WalkEvalOptions& options, double start_yaw_rad, core::Rng* rng,
                      WalkEpisode* ep) {
  double bearing, tyaw;
  if (options.step_suite) {
    ep->dist_m = rng->Uniform(0.5, 1.5);
    ep->bearing_deg = rng->Uniform(60.0, 300.0);
    bearing = start_yaw_rad + ep->bearing_deg * M_PI / 180;
    tyaw = start_yaw_rad;
  } else {
    ep->dist_m = rng->Uniform(options.min_dist_m, options.max_dist_m);
    bearing = rng->Uniform(-M_PI, M_PI);
    tyaw = rng->Uniform(-M_PI, M_PI);
    ep->bearing_deg = std::remainder(bearing - start_yaw_rad, 2 * M_PI) * 180 / M_PI;
  }
  if (ep->bearing_deg > 180) ep->bearing_deg -= 360;
  WalkTarget t;
  t.x_m = ep->dist_m * std::cos(bearing);
  t.y_m = ep->dist_m * std::sin(bearing);
  t.yaw_rad = tyaw;
  return t;
}

// looks up the floor, the foot geoms and the arm bodies (-1: not in the model)
WalkIds FindWalkIds(const mjModel* m) {
  WalkIds ids;
  ids.floor = mj_name2id(m, mjOBJ_GEOM, "floor");
  ids.left_foot = mj_name2id(m, mjOBJ_GEOM, "left_foot_geom");
  ids.right_foot = mj_name2id(m, mjOBJ_GEOM, "right_foot_geom");
  const char* const arm_names[2][2] = {{"left_upper_arm", "left_hand"},
                                       {"right_upper_arm", "right_hand"}};
  for (int s = 0; s < 2; ++s) {
    for (int b = 0; b < 2; ++b) ids.arm_body[s][b] = mj_name2id(m, mjOBJ_BODY, arm_names[s][b]);
  }
  return ids;
}

// the higher arm's angle from hanging straight down (shoulder to hand), rad
double HigherArmRaise(const mjData* d, const WalkIds& ids) {
  double raise = 0;
  for (const auto& b : ids.arm_body) {
    if (b[0] < 0 || b[1] < 0) continue;
    Eigen::Vector3d u(d->xpos[3 * b[1]] - d->xpos[3 * b[0]],
                      d->xpos[3 * b[1] + 1] - d->xpos[3 * b[0] + 1],
                      d->xpos[3 * b[1] + 2] - d->xpos[3 * b[0] + 2]);
    if (u.norm() < 1e-6) continue;
    raise = std::max(raise, core::AngleFromCos(-u.z() / u.norm()));
  }
  return raise;
}

// foot skating: adds the horizontal speed of each foot touching the floor
void AddFootSkate(const mjModel* m, const mjData* d, const WalkIds& ids, WalkTally* tally) {
  for (int c = 0; c < d->ncon; ++c) {
    int g1 = d->contact[c].geom1, g2 = d->contact[c].geom2;
    if (g1 != ids.floor && g2 != ids.floor) continue;
    int g = g1 == ids.floor ? g2 : g1;
    if (g != ids.left_foot && g != ids.right_foot) continue;
    mjtNum vel[6];
    mj_objectVelocity(m, d, mjOBJ_GEOM, g, vel, 0);
    tally->skate += std::hypot(vel[3], vel[4]);
    ++tally->skate_n;
  }
}

// renders episode `i`'s contact sheet (and video) from `traj`; a failure is noted in `ep`
void RenderWalkEpisode(const WalkEvalOptions& options, int i, const world::SimWorld& world,
                       const control::Trajectory& traj, const WalkTarget& target, WalkEpisode* ep) {
  plan::ContactChain chain;
  plan::ContactStep step;
  char label[96];
  std::snprintf(label, sizeof(label), "walk %.1f m to (%.1f, %.1f), face %.0f deg", ep->dist_m,
                target.x_m, target.y_m, target.yaw_rad * 180 / M_PI);
  step.label = label;
  chain.steps.push_back(step);
  ReplayOptions ro;
  std::string base = options.sheet_dir + "/ep" + std::to_string(i);
  ro.sheet_path = base + ".png";
  if (options.video) ro.video_path = base + ".mp4";
  ro.sheet_frames = 16;
  absl::Status rs = RenderReplay(world, chain, traj, ro);
  if (rs.ok()) {
    ep->sheet_path = ro.sheet_path;
  } else {
    ep->render_error = std::string(rs.message());
  }
}

// runs episode `i`: the walker from a random heading to a random target, until it has stayed
// arrived for 15 policy steps, falls or runs out of time. Errors: the policy file, the policy.
core::StatusOr<WalkEpisode> RunWalkEpisode(const WalkEvalOptions& options, int i) {
  using control::kWalkPhysicsDt;
  using control::kWalkSubsteps;
  core::Rng rng(core::DeriveSeed(options.seed, static_cast<uint64_t>(i)));
  world::AgentSpec start;
  start.yaw_rad = rng.Uniform(-M_PI, M_PI);
  start.scale = options.scale;
  world::ModelOptions mo;
  mo.timestep_s = kWalkPhysicsDt;
  mo.solver = options.physics_solver;
  SH_ASSIGN_OR_RETURN(auto world, world::SimWorld::Create(core::SceneCatalog(), {start}, mo));
  world->mutable_model()->nstack = 150000;
  SH_ASSIGN_OR_RETURN(auto walker,
                      control::WalkPolicyController::Load(options.policy, world.get(), 0));
  WalkEpisode ep;
  ep.index = i;
  const WalkTarget target = DrawTarget(options, start.yaw_rad, &rng, &ep);
  walker->SetTarget(target.x_m, target.y_m, target.yaw_rad);
  mjData* d = world->data();
  const mjModel* m = world->model();
  const world::AgentIndex& ix = world->agent(0);
  control::Observation obs;
  obs.world = world.get();
  obs.data = d;
  std::vector<double> ctrl(ix.num_actuators());
  WalkTally tally;
  const int steps = static_cast<int>(options.time_limit_s / kWalkPhysicsDt);
  const bool render = options.video_every > 0 && i % options.video_every == 0;
  control::Trajectory traj;
  traj.nq = m->nq;
  auto record = [&] {
    traj.time_s.push_back(d->time);
    traj.qpos.emplace_back(d->qpos, d->qpos + m->nq);
    traj.step_index.push_back(0);
  };
  SH_ASSIGN_OR_RETURN(const control::WalkIndex wix, control::MakeWalkIndex(*world, 0));
  const WalkIds ids = FindWalkIds(m);
  std::vector<MotionSample> motion;
  for (int k = 0; k < steps; ++k) {
    if (k % kWalkSubsteps == 0) {
      if (render) record();
      obs.time_s = d->time;
      absl::Status st = walker->Act(obs);
      if (!st.ok()) return st;
      if (walker->Arrived(d)) {
        if (++tally.hold >= 15) {
          ep.success = true;
          break;
        }
      } else {
        tally.hold = 0;
      }
    }
    for (int j = 0; j < ix.num_actuators(); ++j) ctrl[j] = d->ctrl[ix.actuator[j]];
    walker->Targets(d->time, ctrl);
    for (int j = 0; j < ix.num_actuators(); ++j) d->ctrl[ix.actuator[j]] = ctrl[j];
    const mjtNum* v = d->qvel + ix.root_qvel;
    tally.path += std::hypot(v[0], v[1]) * kWalkPhysicsDt;
    world::HealthReport h = world->Step();
    if (k % kWalkSubsteps == 0) {
      Eigen::Vector3d pelvis;
      double yaw;
      control::PelvisPose(d, wix, &pelvis, &yaw);
      ep.max_turn_deg = std::max(
          ep.max_turn_deg, std::abs(std::remainder(yaw - start.yaw_rad, 2 * M_PI)) * 180 / M_PI);
      tally.arm_raise += HigherArmRaise(d, ids) * 180 / M_PI;
      ++tally.arm_n;
      motion.push_back(SampleMotion(m, d, *world, 0));
    }
    if (!h.ok() || HeadPointZ(*world, d) < control::kFallHeadHeightM * world->agent(0).scale) {
      ep.fell = true;
      break;
    }
    AddFootSkate(m, d, ids, &tally);
  }
  ep.time_s = d->time;
  if (render) {
    record();
    RenderWalkEpisode(options, i, *world, traj, target, &ep);
  }
  double dist, yaw_err;
  control::WalkErrors(d, wix, walker->state(), &dist, &yaw_err);
  ep.final_dist_m = dist;
  ep.final_yaw_err_deg = std::abs(yaw_err) * 180 / M_PI;
  ep.foot_skate_mps = tally.skate_n ? tally.skate / tally.skate_n : 0;
  ep.mean_speed_mps = ep.time_s > 0 ? tally.path / ep.time_s : 0;
  ep.arm_raise_deg = tally.arm_n ? tally.arm_raise / tally.arm_n : 0;
  ep.motion = ComputeMotionMetrics(motion, options.scale);
  return ep;
}

}  // namespace

core::StatusOr<WalkEvalSummary> RunWalkEval(
    const WalkEvalOptions& options, std::vector<WalkEpisode>* episodes,
    const std::function<void(const WalkEpisode&)>& on_episode) {
  WalkEvalSummary sum;
  int successes = 0, no_turn = 0;
  std::vector<MotionMetrics> motion;
  for (int i = 0; i < options.episodes; ++i) {
    SH_ASSIGN_OR_RETURN(const WalkEpisode ep, RunWalkEpisode(options, i));
    motion.push_back(ep.motion);
    if (episodes) episodes->push_back(ep);
    if (on_episode) on_episode(ep);
    ++sum.episodes;
    sum.fall_rate += ep.fell;
    sum.foot_skate_mps += ep.foot_skate_mps;
    sum.final_dist_m += ep.final_dist_m;
    sum.final_yaw_err_deg += ep.final_yaw_err_deg;
    sum.max_turn_deg += ep.max_turn_deg;
    sum.arm_raise_deg += ep.arm_raise_deg;
    if (ep.success) {
      ++successes;
      no_turn += ep.max_turn_deg < 45.0;
      sum.mean_time_s += ep.time_s;
    }
  }
  if (sum.episodes > 0) {
    sum.success_rate = static_cast<double>(successes) / sum.episodes;
    sum.fall_rate /= sum.episodes;
    sum.foot_skate_mps /= sum.episodes;
    sum.final_dist_m /= sum.episodes;
    sum.final_yaw_err_deg /= sum.episodes;
    sum.max_turn_deg /= sum.episodes;
    sum.arm_raise_deg /= sum.episodes;
  }
  if (successes) {
    sum.mean_time_s /= successes;
    sum.no_turn_rate = static_cast<double>(no_turn) / successes;
  }
  sum.motion = MeanMotionMetrics(motion);
  return sum;
}

nlohmann::ordered_json WalkEpisodeJson(const WalkEpisode& e) {
  nlohmann::ordered_json j;
  j["episode"] = e.index;
  j["dist_m"] = e.dist_m;
  j["success"] = e.success;
  j["fell"] = e.fell;
  j["time_s"] = e.time_s;
  j["final_dist_m"] = e.final_dist_m;
  j["final_yaw_err_deg"] = e.final_yaw_err_deg;
  j["mean_speed_mps"] = e.mean_speed_mps;
  j["foot_skate_mps"] = e.foot_skate_mps;
  j["bearing_deg"] = e.bearing_deg;
  j["max_turn_deg"] = e.max_turn_deg;
  j["arm_raise_deg"] = e.arm_raise_deg;
  j["motion"] = MotionMetricsJson(e.motion);
  if (!e.sheet_path.empty()) j["contact_sheet"] = e.sheet_path;
  return j;
}

nlohmann::ordered_json WalkSummaryJson(const WalkEvalSummary& s, const WalkEvalOptions& options) {
  nlohmann::ordered_json j;
  j["suite"] = options.step_suite ? "walk-step" : "walk";
  j["episodes"] = s.episodes;
  j["success_rate"] = s.success_rate;
  j["fall_rate"] = s.fall_rate;
  j["mean_time_to_success_s"] = s.mean_time_s;
  j["foot_skate_mps"] = s.foot_skate_mps;
  j["final_dist_m"] = s.final_dist_m;
  j["final_yaw_err_deg"] = s.final_yaw_err_deg;
  j["max_turn_deg"] = s.max_turn_deg;
  j["no_turn_rate"] = s.no_turn_rate;
  j["arm_raise_deg"] = s.arm_raise_deg;
  j["physics_solver"] = options.physics_solver;
  j["scale"] = options.scale;
  j["motion"] = MotionMetricsJson(s.motion);
  j["policy"] = options.policy;
  j["seed"] = options.seed;
  const nlohmann::ordered_json provenance = ProvenanceJson();
  for (const auto& [k, v] : provenance.items()) j[k] = v;
  return j;
}

}  // namespace simhuman::eval
