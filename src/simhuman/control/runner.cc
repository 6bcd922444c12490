#include "simhuman/control/runner.h"

#include <algorithm>
#include <chrono>
#include <cmath>

namespace simhuman::control {

std::vector<plan::BodyPoints> AllBodyPoints(const world::SimWorld& world, const mjData* d) {
  std::vector<plan::BodyPoints> out(world.num_agents());
  for (int a = 0; a < world.num_agents(); ++a) {
    out[a].pos_world = world.BodyPoints(d, a);
    double yaw = world::PelvisYaw(d, world.agent(a));
    out[a].facing_world = Eigen::Vector3d(std::cos(yaw), std::sin(yaw), 0);
  }
  return out;
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
  std::vector<double> ctrl(world::kHumanoidDofs);
  const double t_start = d->time;
  double settle_until = -1;  // >= 0 once all steps are done
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
      obs.body_points = world.BodyPoints(d, a);
      if (options.heightmap_size > 0) {
        const mjtNum* pelvis = d->xpos + 3 * world.agent(a).pelvis_body;
        BuildHeightmap(catalog, Eigen::Vector3d(pelvis[0], pelvis[1], pelvis[2]),
                       world::PelvisYaw(d, world.agent(a)), options.heightmap_size,
                       options.heightmap_cell_m, &obs.heightmap);
        obs.heightmap_size = options.heightmap_size;
        obs.heightmap_cell_m = options.heightmap_cell_m;
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
      // falls: head low while the step is not a lying step
      bool lying = tasks[0].posture == Posture::kLieBack || tasks[0].posture == Posture::kLieSide;
      for (int a = 0; a < n_agents; ++a) {
        double head_z = pts[a].at(core::BodyJoint::kHead).z();
        double limit = options.fall_head_height_m * world.agent(a).scale;
        if (head_z < (lying ? 0.25 : limit)) {
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
      controllers[a]->Targets(d->time, ctrl.data());
      const world::AgentIndex& ix = world.agent(a);
      for (int j = 0; j < world::kHumanoidDofs; ++j) d->ctrl[ix.actuator[j]] = ctrl[j];
    }
    double dt = base_dt;
    for (int a = 0; a < n_agents; ++a) {
      double want = controllers[a]->physics_timestep_s();
      if (want > 0) {
        dt = want;
        break;
      }
    }
    world.mutable_model()->opt.timestep = dt;
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
