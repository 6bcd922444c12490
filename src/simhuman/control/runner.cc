#include "simhuman/control/runner.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <memory>

#include "simhuman/perceive/heightmap.h"

namespace simhuman::control {

std::vector<plan::BodyPoints> AllBodyPoints(const world::SimWorld& world, const mjData* d) {
  std::vector<plan::BodyPoints> out(world.num_agents());
  for (int a = 0; a < world.num_agents(); ++a) {
    world.AllBodyPoints(d, a, &out[a].pos_world);
    double yaw = world::PelvisYaw(d, world.agent(a));
    out[a].facing_world = Eigen::Vector3d(std::cos(yaw), std::sin(yaw), 0);
  }
  return out;
}

bool IsFall(Posture posture, double head_z_m, double scale, const RunOptions& options) {
  const bool lying = posture == Posture::kLieBack || posture == Posture::kLieSide;
  return head_z_m < (lying ? kLyingFallHeadHeightM : options.fall_head_height_m * scale);
}

double CommonTimestep(const std::vector<Controller*>& controllers, double world_dt) {
  double dt = 0;
  for (const Controller* c : controllers) {
    double want = c->physics_timestep_s();
    if (want > 0 && (dt == 0 || want < dt)) dt = want;
  }
  return dt > 0 ? dt : world_dt;
}

EpisodeResult RunEpisode(world::SimWorld& world, const plan::ContactChain& chain,
                         const std::vector<Controller*>& controllers, const RunOptions& options,
                         Trajectory* trajectory) {
  auto wall0 = std::chrono::steady_clock::now();
  EpisodeResult res;
  res.steps_total = static_cast<int>(chain.steps.size());
  const mjModel* m = world.model();
  mjData* d = world.data();
  // controllers may ask for their own physics timestep (policies run at their training rate)
  const double base_dt = m->opt.timestep;
  core::SceneCatalog catalog = world.catalog();  // movable poses synced each tick
  plan::StepTracker tracker(chain, options.tracker);
  const int n_agents = world.num_agents();
  std::vector<StepTask> tasks(n_agents);
  std::vector<double> next_act(n_agents, 0.0);
  int task_step = -1;
  double next_frame = 0;
  if (trajectory) {
    *trajectory = Trajectory();
    trajectory->fps = options.record_fps;
    trajectory->nq = m->nq;
  }
  // each agent's span of the model's controls, handed to its controller every physics step
  std::vector<std::vector<double>> ctrl(n_agents);
  for (int a = 0; a < n_agents; ++a) ctrl[a].resize(world.agent(a).num_actuators());
  const double t_start = d->time;
  double settle_until = -1;  // >= 0 once all steps are done
  std::unique_ptr<perceive::HeightmapSensor> heightmap;
  if (options.heightmap_size > 0) {
    heightmap = std::make_unique<perceive::HeightmapSensor>(options.heightmap_size,
                                                            options.heightmap_cell_m);
  }
  auto finish = [&](const std::string& reason) {
    tracker.Finish();
    res.end_reason = reason;
  };

  while (true) {
    double t = d->time - t_start;
    int step = std::min(tracker.current_step(), res.steps_total - 1);
    if (step != task_step) {
      for (int a = 0; a < n_agents; ++a) {
        tasks[a] = BuildStepTask(chain.steps[step], catalog, a, world.agent(a).scale, options.pair);
        if (tasks[a].get_close && step + 1 < res.steps_total) {
          StepTask next =
              BuildStepTask(chain.steps[step + 1], catalog, a, world.agent(a).scale, options.pair);
          RefineApproach(next, world.agent(a).scale, &tasks[a]);
        }
      }
      task_step = step;
    }
    // control ticks
    bool ticked = false;
    for (int a = 0; a < n_agents; ++a) {
      if (t + 1e-9 < next_act[a]) continue;
      ticked = true;
      Observation obs;
      obs.time_s = d->time;
      obs.agent = a;
      obs.world = &world;
      obs.data = d;
      obs.step_index = step;
      obs.task = &tasks[a];
      world.AllBodyPoints(d, a, &obs.body_points);
      if (heightmap) {
        perceive::SensorInput in{&world, d, &catalog, a, d->time};
        perceive::SensorReading reading;
        absl::Status st = heightmap->Read(in, &reading);
        if (!st.ok()) {
          finish("sensor: " + std::string(st.message()));
          break;
        }
        obs.heightmap = std::move(reading.values);
        obs.heightmap_size = heightmap->size();
        obs.heightmap_cell_m = heightmap->cell_m();
      }
      for (const ContactTerm& term : tasks[a].terms) {
        const Eigen::Vector3d& p = obs.body_points[static_cast<int>(term.joint)];
        obs.contact_offsets.push_back(term.Nearest(p, obs.body_points) - p);
      }
      absl::Status st = controllers[a]->Act(obs);
      if (!st.ok()) {
        finish("controller: " + std::string(st.message()));
        break;
      }
      next_act[a] += controllers[a]->control_period_s();
    }
    if (!res.end_reason.empty()) break;
    // plan tracking at control ticks
    if (ticked) {
      world.SyncCatalog(d, &catalog);
      auto pts = AllBodyPoints(world, d);
      plan::StepEval ev = plan::EvaluateStep(chain.steps[step], catalog, pts, options.pair);
      bool was_done = tracker.done();
      if (!was_done) tracker.Update(t, ev);
      if (!was_done && (tracker.current_step() != step || tracker.finished())) {
        ProgressEvent e;
        e.step = step;
        e.steps_total = res.steps_total;
        e.time_s = t;
        e.completed = tracker.current_step() != step;
        double dist = 0;
        int n = 0;
        for (const auto& pe : ev.pairs) {
          dist += pe.distance_m;
          ++n;
        }
        e.distance_m = n ? dist / n : 0;
        e.label = chain.steps[step].label;
        if (options.progress) options.progress(e);
      }
      if (tracker.done() && settle_until < 0) {
        settle_until = t + options.settle_s;
        if (options.settle_s <= 0) {
          finish("completed");
          break;
        }
      }
      if (settle_until >= 0 && t >= settle_until) {
        finish("completed");
        break;
      }
      if (tracker.finished() && !tracker.done()) {
        finish("timeout");
        break;
      }
      // falls: each agent's head against its own step's posture
      for (int a = 0; a < n_agents; ++a) {
        if (IsFall(tasks[a].posture, pts[a].at(core::BodyJoint::kHead).z(), world.agent(a).scale,
                   options)) {
          res.fell = true;
          finish(tracker.done() ? "completed" : "fell");
        }
      }
      if (!res.end_reason.empty()) break;
    }
    // record
    if (trajectory && options.record && t + 1e-9 >= next_frame) {
      trajectory->time_s.push_back(t);
      trajectory->qpos.emplace_back(d->qpos, d->qpos + m->nq);
      trajectory->step_index.push_back(step);
      next_frame += 1.0 / options.record_fps;
    }
    // actuate and step
    for (int a = 0; a < n_agents; ++a) {
      const world::AgentIndex& ix = world.agent(a);
      std::vector<double>& u = ctrl[a];
      for (int j = 0; j < ix.num_actuators(); ++j) u[j] = d->ctrl[ix.actuator[j]];
      controllers[a]->Targets(d->time, u);
      for (int j = 0; j < ix.num_actuators(); ++j) d->ctrl[ix.actuator[j]] = u[j];
    }
    world.mutable_model()->opt.timestep = CommonTimestep(controllers, base_dt);
    world::HealthReport h = world.Step();
    if (!h.ok()) {
      finish(h.reason);
      break;
    }
  }
  world.mutable_model()->opt.timestep = base_dt;
  if (trajectory && options.record) {
    trajectory->time_s.push_back(d->time - t_start);
    trajectory->qpos.emplace_back(d->qpos, d->qpos + m->nq);
    trajectory->step_index.push_back(tracker.current_step());
  }
  res.success = tracker.succeeded();
  res.steps_completed = tracker.steps_completed();
  auto ce = tracker.contact_error_m();
  res.contact_error_m = ce ? *ce : -1;
  res.step_completion_s = tracker.completion_times_s();
  for (const plan::StepRecord& s : tracker.records()) res.pair_errors_m.push_back(s.errors_m);
  res.sim_time_s = d->time - t_start;
  res.wall_time_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - wall0).count();
  if (options.progress) {
    ProgressEvent e;
    e.ended = true;
    e.step = tracker.current_step();
    e.steps_total = res.steps_total;
    e.time_s = res.sim_time_s;
    options.progress(e);
  }
  return res;
}

}  // namespace simhuman::control
