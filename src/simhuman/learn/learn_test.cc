#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>

#include "simhuman/control/policy/policy_net.h"
#include "simhuman/control/policy/walk_task.h"
#include "simhuman/core/testing_temp.h"
#include "simhuman/learn/ppo.h"
#include "simhuman/learn/reach_env.h"
#include "simhuman/learn/vec_env.h"
#include "simhuman/learn/walk_env.h"

namespace simhuman::learn {
namespace {

namespace fs = std::filesystem;

std::string TempDir(const std::string& name) {
  fs::path p = core::testing::UniqueTempPath("learn_test_" + name);
  fs::remove_all(p);
  return p.string();
}

TEST(WorkerPool, VisitsEveryIndexOnce) {
  WorkerPool pool(2);
  for (int round = 0; round < 20; ++round) {
    std::vector<std::atomic<int>> hits(97);
    pool.ParallelFor(97, [&](int i) { hits[i]++; });
    for (auto& h : hits) EXPECT_EQ(h.load(), 1);
  }
}

TEST(VecEnv, SameSeedSameTrajectoryWithOneOrTwoThreads) {
  VecEnv a(std::make_unique<ReachTask>(8), 1, 7), b(std::make_unique<ReachTask>(8), 2, 7);
  a.ResetAll();
  b.ResetAll();
  std::vector<float> act(16);
  for (int t = 0; t < 250; ++t) {
    for (size_t k = 0; k < act.size(); ++k) act[k] = std::sin(0.1f * t + k);
    a.Step(act.data());
    b.Step(act.data());
    ASSERT_EQ(a.obs(), b.obs());
    ASSERT_EQ(a.rewards(), b.rewards());
  }
}

TEST(VecEnv, ChunkedStepMatchesStepAndSeesEachEnvsObservationOnce) {
  // a feedback policy (the action depends on the observation) over 5 uneven chunks of 11 envs
  VecEnv a(std::make_unique<ReachTask>(11), 2, 9), b(std::make_unique<ReachTask>(11), 2, 9);
  a.ResetAll();
  b.ResetAll();
  const int d = a.obs_dim(), na = a.act_dim();
  auto policy = [&](int i, const float* o, float* out) {
    for (int k = 0; k < na; ++k) out[k] = std::tanh(o[k % d] - 0.3f * o[(k + 1) % d]) + 0.01f * i;
  };
  std::vector<float> act(static_cast<size_t>(11) * na);
  for (int t = 0; t < 300; ++t) {
    for (int i = 0; i < 11; ++i) policy(i, a.obs().data() + i * d, act.data() + i * na);
    a.Step(act.data());
    std::vector<std::atomic<int>> seen(11);
    b.StepChunked(
        [&](int begin, int end, const float* obs, float* actions) {
          for (int i = begin; i < end; ++i) {
            ++seen[i];
            policy(i, obs + i * d, actions + i * na);
          }
        },
        5);
    for (auto& s : seen) ASSERT_EQ(s.load(), 1);
    ASSERT_EQ(a.obs(), b.obs()) << t;
    ASSERT_EQ(a.rewards(), b.rewards()) << t;
    ASSERT_EQ(a.finished().size(), b.finished().size()) << t;
  }
}

TEST(VecEnv, TimeLimitTruncatesAndResets) {
  VecEnv env(std::make_unique<ReachTask>(3), 1, 1);
  env.ResetAll();
  std::vector<float> act(6, 0.f);
  for (int t = 0; t < ReachTask::kMaxSteps - 1; ++t) {
    env.Step(act.data());
    EXPECT_TRUE(env.finished().empty());
  }
  env.Step(act.data());
  ASSERT_EQ(env.finished().size(), 3u);
  for (int i = 0; i < 3; ++i) {
    EXPECT_TRUE(env.truncated()[i]);
    EXPECT_FALSE(env.terminated()[i]);
    EXPECT_EQ(env.finished()[i].length, ReachTask::kMaxSteps);
  }
  // the new episode's observation differs from the terminal one
  EXPECT_NE(std::vector<float>(env.obs().begin(), env.obs().begin() + 6),
            std::vector<float>(env.terminal_obs().begin(), env.terminal_obs().begin() + 6));
}

TEST(WalkTask, ObservationsFiniteRewardPositiveFallDetectedIntegration) {
  auto task = WalkTask::Create(2);
  ASSERT_TRUE(task.ok()) << task.status();
  WalkTask& t = **task;
  std::vector<float> obs(control::kWalkObsDim);
  t.Reset(0, 3, obs.data());
  for (float v : obs) ASSERT_TRUE(std::isfinite(v));
  EXPECT_FALSE(t.Fallen(0));
  // the pelvis starts at about the nominal standing height, feet on the floor
  EXPECT_NEAR(obs[0], 0.95, 0.04);
  std::vector<float> act(control::kWalkActDim, 0.f);
  StepInfo info;
  for (int k = 0; k < 10; ++k) {
    t.Step(0, act.data(), obs.data(), &info);
    EXPECT_GT(info.reward, 0.f);
  }
  EXPECT_FALSE(info.terminated);
  // the initial policy's noise (std 0.5) earns a positive reward on average until it falls
  core::Rng rng(5);
  t.Reset(0, 4, obs.data());
  double sum = 0;
  int n = 0;
  for (; n < WalkTask::kMaxSteps && !info.terminated; ++n) {
    for (float& a : act) a = static_cast<float>(rng.Normal(0.5));
    t.Step(0, act.data(), obs.data(), &info);
    sum += info.reward;
  }
  EXPECT_GT(sum / n, 0.2);
  // strong random actions topple it; the fall ends the episode
  t.Reset(0, 5, obs.data());
  bool fell = false;
  for (int k = 0; k < WalkTask::kMaxSteps && !fell; ++k) {
    for (float& a : act) a = static_cast<float>(rng.Normal(2.0));
    t.Step(0, act.data(), obs.data(), &info);
    fell = info.terminated;
  }
  EXPECT_TRUE(fell);
}

// with routes, the target is steered along a random route as the walking controller steers in
// scenes: at a carrot up to kRouteLookaheadM ahead facing it, or (turning first) where the human
// stands; without, every target is straight
TEST(WalkTask, RouteTargetsAreSteeredAsInScenesIntegration) {
  auto task = WalkTask::Create(1);
  ASSERT_TRUE(task.ok()) << task.status();
  WalkTask& t = **task;
  std::vector<float> obs(control::kWalkObsDim), act(control::kWalkActDim, 0.f);
  t.Reset(0, 3, obs.data());
  EXPECT_FALSE(t.on_route(0));
  t.set_route_share(1.0);
  int turning = 0, walking = 0;
  for (uint64_t seed = 1; seed <= 12; ++seed) {
    t.Reset(0, seed, obs.data());
    ASSERT_TRUE(t.on_route(0));
    // the human's root body (its pelvis) is the first after the world's
    const mjtNum* pelvis = t.data(0)->xpos + 3 * t.model()->jnt_bodyid[0];
    const Eigen::Vector2d here(pelvis[0], pelvis[1]);
    const double to_target = (t.state(0).target_xy - here).norm();
    if (to_target < 0.1) {
      ++turning;
    } else {
      ++walking;
      // the carrot's lead, or nearer before a turn (control::SlowForTurn)
      EXPECT_LE(to_target, control::kRouteLookaheadM + 0.05);
      EXPECT_GE(to_target, control::kTurnSlowMinM - 0.05);
      const Eigen::Vector2d way = t.state(0).target_xy - here;
      EXPECT_NEAR(t.state(0).target_yaw_rad, std::atan2(way.y(), way.x()), 1e-9);
    }
    StepInfo info;
    for (int k = 0; k < 5; ++k) t.Step(0, act.data(), obs.data(), &info);
    EXPECT_TRUE(t.on_route(0));
  }
  // first legs point anywhere: some start by turning on the spot, some walk off at once
  EXPECT_GT(turning, 0);
  EXPECT_GT(walking, 0);
}

// the reward weights reach the task: a narrower gait term scores the same state lower, and a
// zero weight leaves it out of the total
TEST(WalkTask, RewardWeightsShapeTheGaitTermIntegration) {
  WalkRewardWeights narrow;
  narrow.gait_legs_width = 0.05;
  WalkRewardWeights none;
  none.gait_legs = 0;
  std::vector<double> term, total;
  for (const WalkRewardWeights& w : {WalkRewardWeights(), narrow, none}) {
    auto task = WalkTask::Create(1, WalkPhysicsSolver::kNewton, {1.0}, "", w);
    ASSERT_TRUE(task.ok()) << task.status();
    std::vector<float> obs(control::kWalkObsDim), act(control::kWalkActDim, 0.3f);
    (*task)->Reset(0, 3, obs.data());
    StepInfo info;
    for (int k = 0; k < 5; ++k) (*task)->Step(0, act.data(), obs.data(), &info);
    term.push_back((*task)->last_terms(0).gait_legs);
    total.push_back(info.reward);
  }
  EXPECT_GT(term[0], 0.0);
  EXPECT_LT(term[1], term[0]);
  EXPECT_NEAR(term[2], term[0], 1e-12);  // the same state and width
  EXPECT_NEAR(total[0] - total[2], 0.1 * term[0], 1e-6);
}

TEST(WalkTask, BodiesOfEverySizeSeeTheAdultsObservationIntegration) {
  // a child (0.6) and a tall adult (1.2) started alike observe the same numbers: the task works
  // in the adult's units (control::WalkScale)
  auto task = WalkTask::Create(2, WalkPhysicsSolver::kNewton, {0.6, 1.2});
  ASSERT_TRUE(task.ok()) << task.status();
  WalkTask& t = **task;
  EXPECT_DOUBLE_EQ(t.body_scale(0), 0.6);
  EXPECT_DOUBLE_EQ(t.body_scale(1), 1.2);
  std::vector<float> child(control::kWalkObsDim), tall(control::kWalkObsDim);
  t.Reset(0, 7, child.data());
  t.Reset(1, 7, tall.data());
  const int pelvis = t.model()->body_rootid[1];
  EXPECT_NEAR(t.data(0)->xpos[3 * pelvis + 2] / t.data(1)->xpos[3 * pelvis + 2], 0.5, 0.01);
  EXPECT_NEAR(child[0], tall[0], 0.01);  // pelvis height / scale
  // every entry but the gait clock (sin, cos of the phase and the amplitude: 105-107), which
  // runs in the adult's time, sqrt(s) faster for the smaller body
  for (int k = 0; k < control::kWalkObsDim; ++k) {
    if (k < 105 || k > 107) {
      EXPECT_NEAR(child[k], tall[k], 0.02) << k;
    }
  }
  const double p0 = t.state(0).phase, p1 = t.state(1).phase;
  std::vector<float> act(control::kWalkActDim, 0.f);
  StepInfo a, b;
  t.Step(0, act.data(), child.data(), &a);
  t.Step(1, act.data(), tall.data(), &b);
  EXPECT_NEAR(t.state(0).cmd.vx, t.state(1).cmd.vx, 0.01);  // adult units
  EXPECT_NEAR((t.state(0).phase - p0) / (t.state(1).phase - p1), std::sqrt(1.2 / 0.6), 1e-6);
  EXPECT_FALSE(WalkTask::Create(1, WalkPhysicsSolver::kNewton, {0.3}).ok());
}

TEST(WalkTask, ReferenceGaitAlternatesFeet) {
  control::WalkParams p;
  control::WalkCommand cmd{1.0, 0, 0};
  int l, r;
  control::WalkExpectedContacts(p, 0.2, 1.0, &l, &r);
  EXPECT_EQ(l, -1);
  EXPECT_EQ(r, 1);
  control::WalkExpectedContacts(p, 0.7, 1.0, &l, &r);
  EXPECT_EQ(l, 1);
  EXPECT_EQ(r, -1);
  double q[control::kWalkActDim];
  control::WalkReference(p, 0.2, 1.0, cmd, q);
  EXPECT_GT(q[24], q[17] + 0.5);  // the swing (left) knee is bent more
  control::WalkReference(p, 0.2, 0.0, cmd, q);
  for (int j = 0; j < control::kWalkActDim; ++j) {
    EXPECT_DOUBLE_EQ(q[j], control::WalkNominalPose()[j]);
  }
}

PpoConfig ReachConfig(const std::string&) {
  PpoConfig c;
  c.task = "reach";
  c.num_envs = 32;
  c.threads = 1;
  c.update_torch_threads = 1;
  c.seed = 3;
  c.rollout_steps = 64;
  c.minibatches = 4;
  c.epochs = 5;
  c.hidden = {64, 64};
  c.lr = 1e-3;
  c.total_steps = 200'000;
  c.checkpoint_every_s = 1e9;
  return c;
}

// A real learning test: the point mass must learn to reach (random policy ~40 per episode).
TEST(Ppo, ReachLearnsWithinBudgetIntegration) {
  constexpr double kReturnThreshold = 75;  // per 100-step episode
  constexpr double kMaxSeconds = 60;
  std::string dir = TempDir("reach");
  auto tr = PpoTrainer::Create(ReachConfig(dir), dir);
  ASSERT_TRUE(tr.ok()) << tr.status();
  auto t0 = std::chrono::steady_clock::now();
  double first = -1, last = 0;
  while (!(*tr)->done()) {
    auto st = (*tr)->Iterate();
    ASSERT_TRUE(st.ok()) << st.status();
    if (first < 0 && st->episodes > 0) first = st->mean_return;
    last = st->mean_return;
  }
  double secs = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  EXPECT_LT(first, 60);
  EXPECT_GT(last, kReturnThreshold) << "first " << first;
  EXPECT_LT(secs, kMaxSeconds);
}

TEST(Ppo, CheckpointResumesAndCorruptionIsAnError) {
  std::string dir = TempDir("resume");
  PpoConfig c = ReachConfig(dir);
  c.total_steps = 4 * 32 * 64;
  {
    auto tr = PpoTrainer::Create(c, dir);
    ASSERT_TRUE(tr.ok()) << tr.status();
    for (int i = 0; i < 2; ++i) ASSERT_TRUE((*tr)->Iterate().ok());
    ASSERT_TRUE((*tr)->Checkpoint().ok());
  }
  EXPECT_EQ(PpoTrainer::Create(c, dir).status().code(), absl::StatusCode::kAlreadyExists);
  auto r = PpoTrainer::Resume(dir);
  ASSERT_TRUE(r.ok()) << r.status();
  EXPECT_EQ((*r)->env_steps(), 2 * 32 * 64);
  while (!(*r)->done()) ASSERT_TRUE((*r)->Iterate().ok());
  EXPECT_TRUE(fs::exists(dir + "/policy.pt"));
  EXPECT_TRUE(ExportPolicy(dir + "/checkpoint.pt", dir + "/small.pt").ok());
  // truncate the checkpoint: resuming must fail, never restart from scratch
  fs::resize_file(dir + "/checkpoint.pt", fs::file_size(dir + "/checkpoint.pt") / 2);
  auto bad = PpoTrainer::Resume(dir);
  EXPECT_EQ(bad.status().code(), absl::StatusCode::kDataLoss) << bad.status();
  EXPECT_EQ(PpoTrainer::Resume(TempDir("none")).status().code(), absl::StatusCode::kNotFound);
}

// rewards turn NaN: the trainer skips the updates and aborts after max_bad_updates
class NanTask : public ReachTask {
 public:
  NanTask() : ReachTask(4) {}
  void Step(int i, const float* action, float* obs, StepInfo* info) override {
    ReachTask::Step(i, action, obs, info);
    info->reward = NAN;
  }
};

TEST(Ppo, NonFiniteUpdatesAbortAfterSeveral) {
  std::string dir = TempDir("nan");
  PpoConfig c = ReachConfig(dir);
  c.num_envs = 4;
  c.rollout_steps = 8;
  c.max_bad_updates = 3;
  auto tr = PpoTrainer::CreateWithTask(c, dir, std::make_unique<NanTask>());
  ASSERT_TRUE(tr.ok()) << tr.status();
  EXPECT_TRUE((*tr)->Iterate().ok());
  EXPECT_TRUE((*tr)->Iterate().ok());
  auto st = (*tr)->Iterate();
  EXPECT_EQ(st.status().code(), absl::StatusCode::kInternal);
}

// a run started from a policy file has that policy's actor and normalizer; during the critic
// warm-up only the value network learns; a policy of other sizes is refused, naming init_from
TEST(Ppo, InitFromCopiesThePolicyAndWarmsUpTheCritic) {
  std::string src_dir = TempDir("init_src"), dir = TempDir("init_dst");
  PpoConfig a = ReachConfig(src_dir);
  a.num_envs = 4;
  a.rollout_steps = 8;
  auto src = PpoTrainer::Create(a, src_dir);
  ASSERT_TRUE(src.ok()) << src.status();
  ASSERT_TRUE((*src)->Iterate().ok());
  ASSERT_TRUE((*src)->Checkpoint().ok());
  const std::string policy = src_dir + "/policy.pt";

  PpoConfig b = a;
  b.seed = 99;  // other random weights, were they not replaced
  b.init_from = policy;
  b.critic_warmup_iters = 2;
  auto dst = PpoTrainer::Create(b, dir);
  ASSERT_TRUE(dst.ok()) << dst.status();
  ASSERT_TRUE((*dst)->Iterate().ok());
  ASSERT_TRUE((*dst)->Checkpoint().ok());
  auto p0 = control::LoadPolicyFile(policy);
  auto p1 = control::LoadPolicyFile(dir + "/policy.pt");
  ASSERT_TRUE(p0.ok() && p1.ok());
  auto w0 = p0->actor->named_parameters(), w1 = p1->actor->named_parameters();
  ASSERT_EQ(w0.size(), w1.size());
  for (const auto& kv : w0) {
    EXPECT_TRUE(torch::equal(kv.value(), w1[kv.key()])) << kv.key() << " changed in warm-up";
  }
  // after the warm-up the policy learns
  ASSERT_TRUE((*dst)->Iterate().ok());
  ASSERT_TRUE((*dst)->Iterate().ok());
  ASSERT_TRUE((*dst)->Checkpoint().ok());
  auto p2 = control::LoadPolicyFile(dir + "/policy.pt");
  ASSERT_TRUE(p2.ok());
  bool changed = false;
  for (const auto& kv : w0)
    changed |= !torch::equal(kv.value(), p2->actor->named_parameters()[kv.key()]);
  EXPECT_TRUE(changed);

  PpoConfig wrong = b;
  wrong.hidden = {32, 32};
  auto bad = PpoTrainer::Create(wrong, TempDir("init_bad"));
  ASSERT_FALSE(bad.ok());
  EXPECT_NE(bad.status().message().find("init_from"), std::string::npos) << bad.status();
  EXPECT_NE(bad.status().message().find("hidden"), std::string::npos) << bad.status();
  PpoConfig missing = b;
  missing.init_from = src_dir + "/no_such_policy.pt";
  const std::string gone_dir = TempDir("init_missing");
  auto gone = PpoTrainer::Create(missing, gone_dir);
  ASSERT_FALSE(gone.ok());
  EXPECT_NE(gone.status().message().find("no_such_policy.pt"), std::string::npos);
  // a run that could not start leaves no folder behind
  EXPECT_FALSE(fs::exists(gone_dir));
}

// a task that ignores its second action entry: PPO gives that entry's noise no weight, so its
// log-std never changes, while the used entry's does; a narrower critic than the actor saves
// and resumes
class FirstActionOnlyReach : public ReachTask {
 public:
  FirstActionOnlyReach() : ReachTask(8) {}
  bool action_used(int j) const override { return j == 0; }
};

TEST(Ppo, UnusedActionEntriesGetNoGradientAndTheCriticHasItsOwnWidths) {
  std::string dir = TempDir("unused");
  PpoConfig c = ReachConfig(dir);
  c.num_envs = 8;
  c.rollout_steps = 16;
  c.critic_hidden = {16};
  c.total_steps = 3 * 8 * 16;
  {
    auto tr = PpoTrainer::CreateWithTask(c, dir, std::make_unique<FirstActionOnlyReach>());
    ASSERT_TRUE(tr.ok()) << tr.status();
    for (int i = 0; i < 2; ++i) ASSERT_TRUE((*tr)->Iterate().ok());
    ASSERT_TRUE((*tr)->Checkpoint().ok());
  }
  auto p = control::LoadPolicyFile(dir + "/policy.pt");
  ASSERT_TRUE(p.ok()) << p.status();
  torch::Tensor log_std = p->actor->log_std();
  const float init = static_cast<float>(std::log(c.init_std));
  EXPECT_FLOAT_EQ(log_std[1].item<float>(), init);
  EXPECT_NE(log_std[0].item<float>(), init);
  EXPECT_EQ(p->meta.hidden, c.hidden);
  // the checkpoint's critic has the critic_hidden widths: resuming rebuilds and loads it
  auto r = PpoTrainer::Resume(dir);
  ASSERT_TRUE(r.ok()) << r.status();
  EXPECT_TRUE((*r)->Iterate().ok());
  EXPECT_FALSE(PpoConfig::FromJson(nlohmann::json{{"critic_hidden", {64, 0}}}).ok());
  auto widths = PpoConfig::FromJson(nlohmann::json{{"critic_hidden", {64}}});
  ASSERT_TRUE(widths.ok()) << widths.status();
  EXPECT_EQ(widths->critic_hidden, std::vector<int>{64});
  // a checkpoint's config from before critic_hidden existed: that run's critic was as wide as
  // the actor, so resuming must build it so (not with today's default widths)
  nlohmann::json legacy = c.ToJson();
  legacy.erase("critic_hidden");
  auto old = PpoConfig::FromCheckpointJson(legacy);
  ASSERT_TRUE(old.ok()) << old.status();
  EXPECT_TRUE(old->critic_hidden.empty());
  auto current = PpoConfig::FromCheckpointJson(c.ToJson());
  ASSERT_TRUE(current.ok()) << current.status();
  EXPECT_EQ(current->critic_hidden, std::vector<int>{16});
  EXPECT_FALSE(PpoConfig::FromCheckpointJson(nlohmann::json{{"learning_rate", 1}}).ok());
}

TEST(PpoConfig, StrictJson) {
  EXPECT_TRUE(PpoConfig::FromJson(nlohmann::json{{"lr", 1e-4}}).ok());
  auto solver = PpoConfig::FromJson(nlohmann::json{{"physics_solver", "cg"}});
  ASSERT_FALSE(solver.ok());
  EXPECT_NE(solver.status().message().find("cg"), std::string::npos) << solver.status();
  auto pgs_reach =
      PpoConfig::FromJson(nlohmann::json{{"physics_solver", "pgs"}, {"task", "reach"}});
  ASSERT_FALSE(pgs_reach.ok());
  EXPECT_NE(pgs_reach.status().message().find("walk task only"), std::string::npos);
  // the default solver, "auto", is valid for every task (pgs for walk, newton for reach)
  EXPECT_EQ(PpoConfig().physics_solver, "auto");
  EXPECT_TRUE(PpoConfig::FromJson(nlohmann::json{{"task", "reach"}}).ok());
  EXPECT_FALSE(PpoConfig::FromJson(nlohmann::json{{"rollout_chunks", -1}}).ok());
  auto bad = PpoConfig::FromJson(nlohmann::json{{"learning_rate", 1e-4}});
  EXPECT_NE(bad.status().message().find("learning_rate"), std::string::npos);
  EXPECT_FALSE(PpoConfig::FromJson(nlohmann::json{{"task", "fly"}}).ok());
}

}  // namespace
}  // namespace simhuman::learn
