#include "simhuman/control/runner.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <memory>

#include "simhuman/control/navigation.h"
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

std::vector<Eigen::Vector3d> JointCentrePelvis(std::vector<Eigen::Vector3d> points) {
  const int l = static_cast<int>(core::BodyJoint::kLeftHip);
  const int r = static_cast<int>(core::BodyJoint::kRightHip);
  if (static_cast<int>(points.size()) > std::max(l, r)) {
    points[static_cast<int>(core::BodyJoint::kPelvis)] = 0.5 * (points[l] + points[r]);
  }
  return points;
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

namespace {

// a walk point keeps this much room (m, times the human's scale) from furniture when the get-close
// radius leaves space for it, and stays this far inside that radius
constexpr double kStandRoomM = 0.2;
constexpr double kStandSpotMarginM = 0.05;

// one episode's loop state; RunEpisode drives it step by step
class EpisodeLoop {
 public:
  EpisodeLoop(world::SimWorld& world, const plan::ContactChain& chain,
              const std::vector<Controller*>& controllers, const RunOptions& options,
              Trajectory* trajectory)
      : world_(world),
        chain_(chain),
        controllers_(controllers),
        options_(options),
        trajectory_(trajectory),
        m_(world.model()),
        d_(world.data()),
        base_dt_(m_->opt.timestep),
        catalog_(world.catalog()),
        tracker_(chain, options.tracker),
        tracker_joint_centre_(chain, options.tracker),
        unihsi_met_(chain.steps.size(), false),
        n_agents_(world.num_agents()),
        tasks_(n_agents_),
        next_act_(n_agents_, 0.0),
        ctrl_(n_agents_),
        t_start_(d_->time) {
    res_.steps_total = static_cast<int>(chain.steps.size());
    if (trajectory_) {
      *trajectory_ = Trajectory();
      trajectory_->fps = options.record_fps;
      trajectory_->nq = m_->nq;
    }
    for (int a = 0; a < n_agents_; ++a) ctrl_[a].resize(world.agent(a).num_actuators());
    if (options.heightmap_size > 0) {
      heightmap_ = std::make_unique<perceive::HeightmapSensor>(options.heightmap_size,
                                                               options.heightmap_cell_m);
    }
  }

  // runs physics steps until the episode ends
  void Run() {
    while (true) {
      const double t = d_->time - t_start_;
      const int step = std::min(tracker_.current_step(), res_.steps_total - 1);
      if (step != task_step_) UpdateTasks(step);
      const bool ticked = ControlTicks(step);
      if (ended()) break;
      if (ticked && (Track(t, step), ended())) break;
      if (Record(t, step), ended()) break;
      if (ActuateAndStep(), ended()) break;
    }
    world_.mutable_model()->opt.timestep = base_dt_;
  }

  // the result, and the last frame and the end event
  EpisodeResult Result(std::chrono::steady_clock::time_point wall0) {
    if (trajectory_ && options_.record) {
      trajectory_->time_s.push_back(d_->time - t_start_);
      trajectory_->qpos.emplace_back(d_->qpos, d_->qpos + m_->nq);
      trajectory_->step_index.push_back(tracker_.current_step());
    }
    res_.success = tracker_.succeeded();
    res_.steps_completed = tracker_.steps_completed();
    auto ce = tracker_.contact_error_m();
    res_.contact_error_m = ce ? *ce : -1;
    auto cj = tracker_joint_centre_.contact_error_m();
    res_.contact_error_joint_centre_m = cj ? *cj : -1;
    res_.success_unihsi_points = res_.success;
    for (bool met : unihsi_met_) res_.success_unihsi_points = res_.success_unihsi_points && met;
    res_.step_completion_s = tracker_.completion_times_s();
    for (const plan::StepRecord& s : tracker_.records()) res_.pair_errors_m.push_back(s.errors_m);
    res_.sim_time_s = d_->time - t_start_;
    res_.wall_time_s =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - wall0).count();
    if (options_.progress) {
      ProgressEvent e;
      e.ended = true;
      e.step = tracker_.current_step();
      e.steps_total = res_.steps_total;
      e.time_s = res_.sim_time_s;
      options_.progress(e);
    }
    return res_;
  }

 private:
  bool ended() const { return !res_.end_reason.empty(); }
  void Finish(const std::string& reason) {
    tracker_.Finish();
    tracker_joint_centre_.Finish();
    res_.end_reason = reason;
  }

  // every agent's task for plan step `step` (a get-close step adapted to the step after it)
  void UpdateTasks(int step) {
    for (int a = 0; a < n_agents_; ++a) {
      const double scale = world_.agent(a).scale;
      tasks_[a] = BuildStepTask(chain_.steps[step], catalog_, a, scale, options_.pair);
      if (tasks_[a].get_close && step + 1 < res_.steps_total) {
        StepTask next = BuildStepTask(chain_.steps[step + 1], catalog_, a, scale, options_.pair);
        RefineApproach(next, scale, &tasks_[a]);
      }
      if (tasks_[a].get_close && step > 0) {
        RefineLeaving(BuildStepTask(chain_.steps[step - 1], catalog_, a, scale, options_.pair),
                      &tasks_[a]);
      } else if (tasks_[a].get_close) {
        // a scene may start the human seated on the object the first step stands up from
        RefineLeavingFromStart(Eigen::Vector3d(d_->qpos + world_.agent(a).root_qpos), scale,
                               &tasks_[a]);
      }
      if (tasks_[a].get_close) {
        // a stand point inside furniture (a chair pushed under a table): stand in the gap
        const StepTask& t = tasks_[a];
        tasks_[a].walk_point.head<2>() = ClearStandingSpot(
            catalog_, t.walk_point.head<2>(), t.stand_point.head<2>(),
            options_.pair.get_close_radius_m - kStandSpotMarginM, kStandRoomM * scale);
      }
    }
    task_step_ = step;
  }

  // calls Act() of every agent whose control tick is due; true if any was
  bool ControlTicks(int step) {
    const double t = d_->time - t_start_;
    bool ticked = false;
    for (int a = 0; a < n_agents_; ++a) {
      if (t + 1e-9 < next_act_[a]) continue;
      ticked = true;
      Observation obs;
      if (!Observe(a, step, &obs)) break;
      absl::Status st = controllers_[a]->Act(obs);
      if (!st.ok()) {
        Finish("controller: " + std::string(st.message()));
        break;
      }
      next_act_[a] += controllers_[a]->control_period_s();
    }
    return ticked;
  }

  // agent `a`'s observation; false (the episode ended) when a sensor failed
  bool Observe(int a, int step, Observation* obs) {
    obs->time_s = d_->time;
    obs->agent = a;
    obs->world = &world_;
    obs->data = d_;
    obs->step_index = step + options_.controller_step_offset;
    obs->task = &tasks_[a];
    obs->behind_real_time =
        options_.behind_real_time && options_.behind_real_time(d_->time - t_start_);
    world_.AllBodyPoints(d_, a, &obs->body_points);
    if (heightmap_) {
      perceive::SensorInput in{&world_, d_, &catalog_, a, d_->time};
      perceive::SensorReading reading;
      absl::Status st = heightmap_->Read(in, &reading);
      if (!st.ok()) {
        Finish("sensor: " + std::string(st.message()));
        return false;
      }
      obs->heightmap = std::move(reading.values);
      obs->heightmap_size = heightmap_->size();
      obs->heightmap_cell_m = heightmap_->cell_m();
    }
    for (const ContactTerm& term : tasks_[a].terms) {
      const Eigen::Vector3d& p = obs->body_points[static_cast<int>(term.joint)];
      obs->contact_offsets.push_back(term.Nearest(p, obs->body_points) - p);
    }
    return true;
  }

  // plan tracking at a control tick: step completion, progress, settling, timeout, falls
  void Track(double t, int step) {
    world_.SyncCatalog(d_, &catalog_);
    auto pts = AllBodyPoints(world_, d_);
    plan::StepEval ev = plan::EvaluateStep(chain_.steps[step], catalog_, pts, options_.pair);
    bool was_done = tracker_.done();
    if (!was_done) {
      tracker_.Update(t, ev);
      // the same completions, errors measured from UniHSI's pelvis point
      std::vector<plan::BodyPoints> jc = pts;
      for (plan::BodyPoints& p : jc) p.pos_world = JointCentrePelvis(std::move(p.pos_world));
      plan::PairParams unihsi = options_.pair;
      unihsi.hand_on_pelvis_at_belly = false;
      plan::StepEval ev_jc = plan::EvaluateStep(chain_.steps[step], catalog_, jc, unihsi);
      if (ev_jc.complete) unihsi_met_[step] = true;
      ev_jc.complete = ev.complete;
      tracker_joint_centre_.Update(t, ev_jc);
    }
    if (!was_done && (tracker_.current_step() != step || tracker_.finished())) {
      Progress(t, step, ev);
    }
    if (tracker_.done() && settle_until_ < 0) {
      settle_until_ = t + options_.settle_s;
      if (options_.settle_s <= 0) return Finish("completed");
    }
    if (settle_until_ >= 0 && t >= settle_until_) return Finish("completed");
    if (tracker_.finished() && !tracker_.done()) return Finish("timeout");
    // falls: each agent's head against its own step's posture
    for (int a = 0; a < n_agents_; ++a) {
      if (IsFall(tasks_[a].posture, pts[a].at(core::BodyJoint::kHead).z(), world_.agent(a).scale,
                 options_)) {
        res_.fell = true;
        Finish(tracker_.done() ? "completed" : "fell");
      }
    }
  }

  // reports a step that completed (or the plan that ran out of time)
  void Progress(double t, int step, const plan::StepEval& ev) const {
    ProgressEvent e;
    e.step = step;
    e.steps_total = res_.steps_total;
    e.time_s = t;
    e.completed = tracker_.current_step() != step;
    double dist = 0;
    int n = 0;
    for (const auto& pe : ev.pairs) {
      dist += pe.distance_m;
      ++n;
    }
    e.distance_m = n ? dist / n : 0;
    e.label = chain_.steps[step].label;
    if (options_.progress) options_.progress(e);
  }

  // a frame every 1/record_fps s: recorded, and shown to on_frame (which may interrupt)
  void Record(double t, int step) {
    if (t + 1e-9 < next_frame_) return;
    next_frame_ += 1.0 / options_.record_fps;
    if (trajectory_ && options_.record) {
      trajectory_->time_s.push_back(t);
      trajectory_->qpos.emplace_back(d_->qpos, d_->qpos + m_->nq);
      trajectory_->step_index.push_back(step);
    }
    if (options_.on_frame && !options_.on_frame(t, step)) Finish("interrupted");
  }

  // every agent's controller writes its actuator span; one physics step with a health check
  void ActuateAndStep() {
    for (int a = 0; a < n_agents_; ++a) {
      const world::AgentIndex& ix = world_.agent(a);
      std::vector<double>& u = ctrl_[a];
      for (int j = 0; j < ix.num_actuators(); ++j) u[j] = d_->ctrl[ix.actuator[j]];
      controllers_[a]->Targets(d_->time, u);
      for (int j = 0; j < ix.num_actuators(); ++j) d_->ctrl[ix.actuator[j]] = u[j];
    }
    world_.mutable_model()->opt.timestep = CommonTimestep(controllers_, base_dt_);
    world::HealthReport h = world_.Step();
    if (!h.ok()) Finish(h.reason);
  }

  world::SimWorld& world_;
  const plan::ContactChain& chain_;
  const std::vector<Controller*>& controllers_;
  const RunOptions& options_;
  Trajectory* trajectory_;
  const mjModel* m_;
  mjData* d_;
  const double base_dt_;        // the world's own timestep, restored at the end
  core::SceneCatalog catalog_;  // movable poses synced each tick
  plan::StepTracker tracker_;
  plan::StepTracker tracker_joint_centre_;  // contact error with the joint-centre pelvis
  std::vector<bool> unihsi_met_;            // per step: its pairs met once on UniHSI's body points
  const int n_agents_;
  std::vector<StepTask> tasks_;
  std::vector<double> next_act_;
  std::vector<std::vector<double>> ctrl_;  // each agent's span of the model's controls
  const double t_start_;
  int task_step_ = -1;
  double next_frame_ = 0;
  double settle_until_ = -1;  // >= 0 once all steps are done
  std::unique_ptr<perceive::HeightmapSensor> heightmap_;
  EpisodeResult res_;
};

}  // namespace

EpisodeResult RunEpisode(world::SimWorld& world, const plan::ContactChain& chain,
                         const std::vector<Controller*>& controllers, const RunOptions& options,
                         Trajectory* trajectory) {
  auto wall0 = std::chrono::steady_clock::now();
  EpisodeLoop loop(world, chain, controllers, options, trajectory);
  loop.Run();
  return loop.Result(wall0);
}

}  // namespace simhuman::control
