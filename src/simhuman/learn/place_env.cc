#include "simhuman/learn/place_env.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <condition_variable>
#include <mutex>
#include <thread>

#include "simhuman/control/manip/scripted_grasp.h"
#include "simhuman/control/manip/table_world.h"
#include "simhuman/control/manip/tabletop_pipeline.h"
#include "simhuman/core/rng.h"

namespace simhuman::learn {

namespace cm = control::manip;

namespace {
// thrown out of the pipeline's place callback when the trainer abandons the episode (a reset
// mid-episode, or the task's end)
struct Abandoned {};
}  // namespace

float PlaceEpisodeReward(bool success, double dxy_m, double up_z) {
  const double cos30 = std::cos(M_PI / 6);
  const double upright = std::clamp((up_z - cos30) / (1 - cos30), 0.0, 1.0);
  const double near = std::exp(-(dxy_m / 0.03) * (dxy_m / 0.03));
  return static_cast<float>((success ? 2.0 : 0.0) + near + upright);
}

struct PlaceTask::Env {
  std::mutex mu;
  std::condition_variable cv;
  std::thread thread;
  // trainer -> env
  bool has_seed = false, has_action = false, abandon = false, stop = false;
  uint64_t seed = 0;
  float action[cm::kPlaceActDim] = {};
  // env -> trainer
  bool posted = false, ended = false, success = false, waiting = false;
  float reward = 0;
  float obs[cm::kPlaceObsDim] = {};
  std::atomic<int> scenes{0};
  // the scene placing starts from, and how many more episodes start from it
  cm::TabletopOptions options;
  cm::TableWorld tw;
  cm::GraspIndex ix;
  cm::PlaceStart start;
  int uses_left = 0;

  // a new scene run up to where placing begins; false when it does not get there
  bool NewScene(uint64_t scene_seed);

  void Loop();
  // one episode: placing from the current scene's start (a new scene from `episode_seed` when
  // that one is used up)
  void RunEpisode(uint64_t episode_seed);
  // the place callback: posts `o`, waits for the trainer's action
  void Decide(const float* o, float* act);
  void Post(bool ended_now, float r, bool ok);
};

void PlaceTask::Env::Post(bool ended_now, float r, bool ok) {
  std::lock_guard<std::mutex> lock(mu);
  posted = true;
  ended = ended_now;
  reward = r;
  success = ok;
  cv.notify_all();
}

void PlaceTask::Env::Decide(const float* o, float* act) {
  std::unique_lock<std::mutex> lock(mu);
  std::copy(o, o + cm::kPlaceObsDim, obs);
  posted = true;
  ended = false;
  reward = 0;
  success = false;
  waiting = true;
  cv.notify_all();
  cv.wait(lock, [&] { return has_action || abandon || stop; });
  waiting = false;
  if (!has_action) {
    abandon = false;
    throw Abandoned{};
  }
  has_action = false;
  std::copy(action, action + cm::kPlaceActDim, act);
}

bool PlaceTask::Env::NewScene(uint64_t scene_seed) {
  const std::string kind = (scene_seed >> 7) % 2 == 0 ? "place" : "stack";
  ++scenes;
  uses_left = 0;
  core::StatusOr<cm::TableWorld> made = cm::MakeTableWorld(scene_seed, kind);
  if (!made.ok()) return false;
  tw = std::move(*made);
  core::StatusOr<cm::GraspIndex> made_ix = cm::MakeGraspIndex(*tw.world, 0, true);
  core::StatusOr<cm::TabletopGoal> goal = cm::TabletopSceneGoal(tw.ts, *tw.world);
  if (!made_ix.ok() || !goal.ok()) return false;
  ix = std::move(*made_ix);
  const mjModel* m = tw.world->model();
  const mjData* d = tw.world->data();
  const cm::GraspPolicyFactory grasp = [&](const cm::TabletopGoal& g) {
    return cm::MakeScriptedGrasp(m, d, ix, g, options);
  };
  cm::RunTabletopToPlace(*tw.world, ix, *goal, grasp, options, &start);
  if (!start.ready()) return false;
  uses_left = kEpisodesPerScene;
  return true;
}

void PlaceTask::Env::RunEpisode(uint64_t episode_seed) {
  for (int k = 0; uses_left == 0; ++k) {
    if (k == kMaxScenesPerEpisode) {
      // no scene reached placing: an episode that starts and ends at once
      float zeros[cm::kPlaceObsDim] = {};
      float ignored[cm::kPlaceActDim];
      Decide(zeros, ignored);
      Post(true, 0, false);
      return;
    }
    NewScene(core::DeriveSeed(episode_seed, 0x91ace, static_cast<uint64_t>(k)));
  }
  --uses_left;
  const cm::PlacePolicyFn place = [&](const float* o, float* act) { Decide(o, act); };
  const cm::TabletopResult r = cm::RunTabletopPlace(*tw.world, ix, start, options, place);
  const int body = start.goal.object_body;
  const Eigen::Vector3d& target = start.goal.target;
  const double dxy = std::hypot(r.final_pos.x() - target.x(), r.final_pos.y() - target.y());
  Post(true, PlaceEpisodeReward(r.success, dxy, tw.world->data()->xmat[9 * body + 8]), r.success);
}

void PlaceTask::Env::Loop() {
  for (;;) {
    uint64_t s;
    {
      std::unique_lock<std::mutex> lock(mu);
      cv.wait(lock, [&] { return has_seed || stop; });
      if (stop) return;
      has_seed = false;
      s = seed;
    }
    try {
      RunEpisode(s);
    } catch (const Abandoned&) {
    }
  }
}

core::StatusOr<std::unique_ptr<PlaceTask>> PlaceTask::Create(int num_envs) {
  if (num_envs <= 0) return absl::InvalidArgumentError("place task: --envs must be positive");
  // one scene built up front, so a broken build fails here rather than in the threads
  SH_ASSIGN_OR_RETURN(cm::TableWorld probe, cm::MakeTableWorld(1, "stack"));
  std::unique_ptr<PlaceTask> t(new PlaceTask());
  for (int i = 0; i < num_envs; ++i) {
    t->envs_.push_back(std::make_unique<Env>());
    Env* e = t->envs_.back().get();
    e->thread = std::thread([e] { e->Loop(); });
  }
  return t;
}

PlaceTask::~PlaceTask() {
  for (auto& e : envs_) {
    {
      std::lock_guard<std::mutex> lock(e->mu);
      e->stop = true;
    }
    e->cv.notify_all();
  }
  for (auto& e : envs_) e->thread.join();
}

int PlaceTask::scenes_run(int i) const { return envs_[i]->scenes.load(); }

void PlaceTask::Reset(int i, uint64_t seed, float* obs) {
  Env& e = *envs_[i];
  std::unique_lock<std::mutex> lock(e.mu);
  if (e.waiting) e.abandon = true;  // the episode under way is dropped
  e.has_action = false;
  e.posted = false;
  e.seed = seed;
  e.has_seed = true;
  e.cv.notify_all();
  e.cv.wait(lock, [&] { return e.posted && !e.abandon; });
  e.posted = false;
  std::copy(e.obs, e.obs + cm::kPlaceObsDim, obs);
}

void PlaceTask::Step(int i, const float* action, float* obs, StepInfo* info) {
  Env& e = *envs_[i];
  std::unique_lock<std::mutex> lock(e.mu);
  for (int k = 0; k < cm::kPlaceActDim; ++k) {
    e.action[k] = std::isfinite(action[k]) ? std::clamp(action[k], -1.0f, 1.0f) : 0.0f;
  }
  e.has_action = true;
  e.posted = false;
  e.cv.notify_all();
  e.cv.wait(lock, [&] { return e.posted; });
  e.posted = false;
  std::copy(e.obs, e.obs + cm::kPlaceObsDim, obs);
  info->reward = e.reward;
  info->terminated = e.ended;
  info->truncated = false;
  info->success = e.success;
}

}  // namespace simhuman::learn
