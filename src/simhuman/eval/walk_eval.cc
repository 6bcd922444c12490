#include "simhuman/eval/walk_eval.h"

#include <algorithm>
#include <cmath>

#include "simhuman/control/policy/policy_controller.h"
#include "simhuman/control/policy/walk_task.h"
#include "simhuman/core/rng.h"
#include "simhuman/eval/episode.h"
#include "simhuman/eval/replay.h"
#include "simhuman/world/sim_world.h"

namespace simhuman::eval {

core::StatusOr<WalkEvalSummary> RunWalkEval(
    const WalkEvalOptions& options, std::vector<WalkEpisode>* episodes,
    const std::function<void(const WalkEpisode&)>& on_episode) {
  using control::kWalkPhysicsDt;
  using control::kWalkSubsteps;
  WalkEvalSummary sum;
  int successes = 0, no_turn = 0;
  for (int i = 0; i < options.episodes; ++i) {
    core::Rng rng(core::DeriveSeed(options.seed, static_cast<uint64_t>(i)));
    world::AgentSpec start;
    start.yaw_rad = rng.Uniform(-M_PI, M_PI);
    world::ModelOptions mo;
    mo.timestep_s = kWalkPhysicsDt;
    mo.solver = options.physics_solver;
    SH_ASSIGN_OR_RETURN(auto world, world::SimWorld::Create(core::SceneCatalog(), {start}, mo));
    world->mutable_model()->nstack = 150000;
    SH_ASSIGN_OR_RETURN(auto walker,
                        control::WalkPolicyController::Load(options.policy, world.get(), 0));
    WalkEpisode ep;
    ep.index = i;
    double bearing, tyaw;
    if (options.step_suite) {
      ep.dist_m = rng.Uniform(0.5, 1.5);
      ep.bearing_deg = rng.Uniform(60.0, 300.0);
      bearing = start.yaw_rad + ep.bearing_deg * M_PI / 180;
      tyaw = start.yaw_rad;
    } else {
      ep.dist_m = rng.Uniform(options.min_dist_m, options.max_dist_m);
      bearing = rng.Uniform(-M_PI, M_PI);
      tyaw = rng.Uniform(-M_PI, M_PI);
      ep.bearing_deg = std::remainder(bearing - start.yaw_rad, 2 * M_PI) * 180 / M_PI;
    }
    if (ep.bearing_deg > 180) ep.bearing_deg -= 360;
    double tx = ep.dist_m * std::cos(bearing), ty = ep.dist_m * std::sin(bearing);
    walker->SetTarget(tx, ty, tyaw);
    mjData* d = world->data();
    const mjModel* m = world->model();
    const world::AgentIndex& ix = world->agent(0);
    control::Observation obs;
    obs.world = world.get();
    obs.data = d;
    std::vector<double> ctrl(ix.num_actuators());
    int hold = 0;
    double skate = 0, path = 0;
    long skate_n = 0;
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
    const int floor = mj_name2id(m, mjOBJ_GEOM, "floor");
    int lf = mj_name2id(m, mjOBJ_GEOM, "left_foot_geom"),
        rf = mj_name2id(m, mjOBJ_GEOM, "right_foot_geom");
    const int arm_body[2][2] = {
        {mj_name2id(m, mjOBJ_BODY, "left_upper_arm"), mj_name2id(m, mjOBJ_BODY, "left_hand")},
        {mj_name2id(m, mjOBJ_BODY, "right_upper_arm"), mj_name2id(m, mjOBJ_BODY, "right_hand")}};
    double arm_raise = 0;
    long arm_n = 0;
    for (int k = 0; k < steps; ++k) {
      if (k % kWalkSubsteps == 0) {
        if (render) record();
        obs.time_s = d->time;
        absl::Status st = walker->Act(obs);
        if (!st.ok()) return st;
        if (walker->Arrived(d)) {
          if (++hold >= 15) {
            ep.success = true;
            break;
          }
        } else {
          hold = 0;
        }
      }
      for (int j = 0; j < ix.num_actuators(); ++j) ctrl[j] = d->ctrl[ix.actuator[j]];
      walker->Targets(d->time, ctrl);
      for (int j = 0; j < ix.num_actuators(); ++j) d->ctrl[ix.actuator[j]] = ctrl[j];
      const mjtNum* v = d->qvel + ix.root_qvel;
      path += std::hypot(v[0], v[1]) * kWalkPhysicsDt;
      world::HealthReport h = world->Step();
      if (k % kWalkSubsteps == 0) {
        Eigen::Vector3d pelvis;
        double yaw;
        control::PelvisPose(d, wix, &pelvis, &yaw);
        ep.max_turn_deg = std::max(
            ep.max_turn_deg, std::abs(std::remainder(yaw - start.yaw_rad, 2 * M_PI)) * 180 / M_PI);
        // the higher arm's angle from hanging straight down (shoulder to hand)
        double raise = 0;
        for (const auto& b : arm_body) {
          if (b[0] < 0 || b[1] < 0) continue;
          Eigen::Vector3d u(d->xpos[3 * b[1]] - d->xpos[3 * b[0]],
                            d->xpos[3 * b[1] + 1] - d->xpos[3 * b[0] + 1],
                            d->xpos[3 * b[1] + 2] - d->xpos[3 * b[0] + 2]);
          if (u.norm() < 1e-6) continue;
          raise = std::max(raise, std::acos(std::clamp(-u.z() / u.norm(), -1.0, 1.0)));
        }
        arm_raise += raise * 180 / M_PI;
        ++arm_n;
      }
      if (!h.ok() || d->xpos[3 * ix.head_body + 2] < 0.8) {
        ep.fell = true;
        break;
      }
      // foot skating: horizontal speed of feet touching the floor
      for (int c = 0; c < d->ncon; ++c) {
        int g1 = d->contact[c].geom1, g2 = d->contact[c].geom2;
        if (g1 != floor && g2 != floor) continue;
        int g = g1 == floor ? g2 : g1;
        if (g != lf && g != rf) continue;
        mjtNum vel[6];
        mj_objectVelocity(m, d, mjOBJ_GEOM, g, vel, 0);
        skate += std::hypot(vel[3], vel[4]);
        ++skate_n;
      }
    }
    ep.time_s = d->time;
    if (render) {
      record();
      plan::ContactChain chain;
      plan::ContactStep step;
      char label[96];
      std::snprintf(label, sizeof(label), "walk %.1f m to (%.1f, %.1f), face %.0f deg", ep.dist_m,
                    tx, ty, tyaw * 180 / M_PI);
      step.label = label;
      chain.steps.push_back(step);
      ReplayOptions ro;
      std::string base = options.sheet_dir + "/ep" + std::to_string(i);
      ro.sheet_path = base + ".png";
      if (options.video) ro.video_path = base + ".mp4";
      ro.sheet_frames = 16;
      absl::Status rs = RenderReplay(*world, chain, traj, ro);
      if (rs.ok()) {
        ep.sheet_path = ro.sheet_path;
      } else {
        ep.render_error = std::string(rs.message());
      }
    }
    double dist, yaw_err;
    control::WalkErrors(d, wix, walker->state(), &dist, &yaw_err);
    ep.final_dist_m = dist;
    ep.final_yaw_err_deg = std::abs(yaw_err) * 180 / M_PI;
    ep.foot_skate_mps = skate_n ? skate / skate_n : 0;
    ep.mean_speed_mps = ep.time_s > 0 ? path / ep.time_s : 0;
    ep.arm_raise_deg = arm_n ? arm_raise / arm_n : 0;
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
  j["policy"] = options.policy;
  j["seed"] = options.seed;
  const nlohmann::ordered_json provenance = ProvenanceJson();
  for (const auto& [k, v] : provenance.items()) j[k] = v;
  return j;
}

}  // namespace simhuman::eval
