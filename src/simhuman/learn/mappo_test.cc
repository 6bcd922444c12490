// The multi-agent interface (MultiAgentVecEnv, the team_carry toy task, the team rollout) and
// the MAPPO trainer.
#include "simhuman/learn/mappo.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <vector>

#include "simhuman/control/policy/policy_net.h"
#include "simhuman/core/rng.h"
#include "simhuman/core/testing_temp.h"
#include "simhuman/learn/multi_agent_env.h"
#include "simhuman/learn/multi_agent_tasks.h"
#include "simhuman/learn/team_carry_env.h"
#include "simhuman/learn/team_rollout.h"

namespace simhuman::learn {
namespace {

namespace fs = std::filesystem;

std::string TempDir(const std::string& name) {
  fs::path p = core::testing::UniqueTempPath("mappo_test_" + name);
  fs::remove_all(p);
  return p.string();
}

// agent a of env i observes (i, a, step); its reward is its own first action entry plus 100 a;
// the shared state is (i, step); episodes last kSteps steps
class ProbeTeamTask : public MultiAgentVecTask {
 public:
  static constexpr int kSteps = 5;
  ProbeTeamTask(int envs, int agents) : steps_(envs, 0), agents_(agents) {}
  std::string name() const override { return "probe"; }
  int num_envs() const override { return static_cast<int>(steps_.size()); }
  int num_agents() const override { return agents_; }
  int obs_dim() const override { return 3; }
  int act_dim() const override { return 2; }
  int state_dim() const override { return 2; }
  void Reset(int i, uint64_t, float* obs, float* state) override {
    steps_[i] = 0;
    Observe(i, obs, state);
  }
  void Step(int i, const float* actions, float* obs, float* state, float* rewards,
            TeamStepInfo* info) override {
    ++steps_[i];
    for (int a = 0; a < agents_; ++a) rewards[a] = actions[2 * a] + 100.f * a;
    Observe(i, obs, state);
    info->truncated = steps_[i] >= kSteps;
  }

 private:
  void Observe(int i, float* obs, float* state) const {
    for (int a = 0; a < agents_; ++a) {
      obs[3 * a] = static_cast<float>(i);
      obs[3 * a + 1] = static_cast<float>(a);
      obs[3 * a + 2] = static_cast<float>(steps_[i]);
    }
    state[0] = static_cast<float>(i);
    state[1] = static_cast<float>(steps_[i]);
  }
  std::vector<int> steps_;
  int agents_;
};

TEST(MultiAgentVecEnv, ShapesAndEachAgentGetsItsOwnActionAndReward) {
  const int E = 4, N = 3;
  MultiAgentVecEnv env(std::make_unique<ProbeTeamTask>(E, N), 2, 1);
  env.ResetAll();
  ASSERT_EQ(env.obs().size(), static_cast<size_t>(E * N * 3));
  ASSERT_EQ(env.state().size(), static_cast<size_t>(E * 2));
  std::vector<float> act(E * N * 2, 0.f);
  for (int r = 0; r < E * N; ++r) act[2 * r] = static_cast<float>(r);
  env.Step(act.data());
  ASSERT_EQ(env.rewards().size(), static_cast<size_t>(E * N));
  ASSERT_EQ(env.terminated().size(), static_cast<size_t>(E));
  for (int r = 0; r < E * N; ++r) {
    const int i = r / N, a = r % N;
    EXPECT_FLOAT_EQ(env.rewards()[r], r + 100.f * a) << "row " << r;
    EXPECT_FLOAT_EQ(env.obs()[3 * r], i);
    EXPECT_FLOAT_EQ(env.obs()[3 * r + 1], a);
  }
  // the team ends together at the time limit; each agent's return is its own
  for (int t = 1; t < ProbeTeamTask::kSteps; ++t) env.Step(act.data());
  ASSERT_EQ(env.finished().size(), static_cast<size_t>(E));
  for (int i = 0; i < E; ++i) {
    EXPECT_TRUE(env.truncated()[i]);
    const TeamEpisodeStats& e = env.finished()[i];
    ASSERT_EQ(e.agent_returns.size(), static_cast<size_t>(N));
    double mean = 0;
    for (int a = 0; a < N; ++a) {
      const int r = i * N + a;
      EXPECT_DOUBLE_EQ(e.agent_returns[a], ProbeTeamTask::kSteps * (r + 100.0 * a));
      mean += e.agent_returns[a] / N;
    }
    EXPECT_DOUBLE_EQ(e.team.ret, mean);
    EXPECT_EQ(e.team.length, ProbeTeamTask::kSteps);
    EXPECT_FLOAT_EQ(env.terminal_state()[2 * i + 1], ProbeTeamTask::kSteps);
    EXPECT_FLOAT_EQ(env.state()[2 * i + 1], 0);  // the new episode
  }
}

TEST(MultiAgentVecEnv, EpisodesAreSeededPerSeedEnvAndEpisodeWhateverTheThreads) {
  const int E = 5, N = 2, D = 10, S = 12;
  MultiAgentVecEnv a(std::make_unique<TeamCarryTask>(E, N), 1, 11);
  MultiAgentVecEnv b(std::make_unique<TeamCarryTask>(E, N), 2, 11);
  a.ResetAll();
  b.ResetAll();
  ASSERT_EQ(a.obs_dim(), D);
  ASSERT_EQ(a.state_dim(), S);
  // env i's first episode is the task's episode of DeriveSeed(seed, i, 0)
  TeamCarryTask single(1, N);
  std::vector<float> obs(N * D), state(S);
  for (int i = 0; i < E; ++i) {
    single.Reset(0, core::DeriveSeed(11, i, 0), obs.data(), state.data());
    EXPECT_EQ(obs,
              std::vector<float>(a.obs().begin() + i * N * D, a.obs().begin() + (i + 1) * N * D));
    EXPECT_EQ(state,
              std::vector<float>(a.state().begin() + i * S, a.state().begin() + (i + 1) * S));
  }
  std::vector<float> act(E * N * 2);
  for (int t = 0; t < 2 * TeamCarryTask::kMaxSteps + 10; ++t) {
    for (size_t k = 0; k < act.size(); ++k) act[k] = std::sin(0.07f * t + k);
    a.Step(act.data());
    b.Step(act.data());
    ASSERT_EQ(a.obs(), b.obs()) << t;
    ASSERT_EQ(a.state(), b.state()) << t;
    ASSERT_EQ(a.rewards(), b.rewards()) << t;
  }
  // another seed, other episodes
  MultiAgentVecEnv c(std::make_unique<TeamCarryTask>(E, N), 1, 12);
  c.ResetAll();
  MultiAgentVecEnv d(std::make_unique<TeamCarryTask>(E, N), 1, 11);
  d.ResetAll();
  EXPECT_NE(c.state(), d.state());
}

// a scripted policy on the observations: go to the box, and once every agent holds it, push
// toward the goal
void ScriptedCarry(const float* obs, int n, int d, bool all_help, float* act) {
  bool all_near = true;
  for (int a = 0; a < n; ++a) {
    all_near = all_near && std::hypot(obs[a * d + 4], obs[a * d + 5]) < 0.8 * TeamCarryTask::kGripM;
  }
  for (int a = 0; a < n; ++a) {
    const float* o = obs + a * d;
    for (int k = 0; k < 2; ++k) {
      float f =
          all_near ? 3.f * o[6 + k] + o[4 + k] - 0.8f * o[2 + k] : 3.f * o[4 + k] - 1.5f * o[2 + k];
      act[2 * a + k] = (all_help || a == 0) ? f : 0.f;
    }
  }
}

TEST(TeamCarryTask, PerAgentRewardsAndTheBoxMovesOnlyWhenEveryAgentHoldsIt) {
  constexpr float kRewardTol = 1e-5f;
  constexpr int kEpisodes = 10;
  const int N = 2, D = 10, S = 12;
  double team_return = 0, lone_return = 0;
  int successes = 0;
  for (bool all_help : {true, false}) {
    TeamCarryTask task(1, N);
    for (int ep = 0; ep < kEpisodes; ++ep) {
      std::vector<float> obs(N * D), state(S), act(N * 2), rew(N);
      task.Reset(0, core::DeriveSeed(42, ep), obs.data(), state.data());
      const float box0[2] = {state[4 * N], state[4 * N + 1]};
      bool moved = false;
      TeamStepInfo info;
      for (int t = 0; t < TeamCarryTask::kMaxSteps; ++t) {
        ScriptedCarry(obs.data(), N, D, all_help, act.data());
        task.Step(0, act.data(), obs.data(), state.data(), rew.data(), &info);
        // agent a's reward: its own approach term plus the team's term, from its observation
        for (int a = 0; a < N; ++a) {
          const float* o = obs.data() + a * D;
          const double scale = TeamCarryTask::kRewardScaleM;
          double expect =
              TeamCarryTask::kApproachWeight * std::exp(-std::hypot(o[4], o[5]) / scale) +
              std::exp(-std::hypot(o[6], o[7]) / scale);
          ASSERT_NEAR(rew[a], expect, kRewardTol) << "agent " << a << " step " << t;
        }
        moved = moved || state[4 * N] != box0[0] || state[4 * N + 1] != box0[1];
        (all_help ? team_return : lone_return) += rew[0] / kEpisodes;
      }
      EXPECT_EQ(info.truncated, true);
      if (all_help) successes += info.success;
      if (!all_help) {
        EXPECT_FALSE(moved) << "one agent moved the box alone, episode " << ep;
      }
    }
  }
  // the scripted team brings the box to the goal in most episodes
  EXPECT_GE(successes, kEpisodes / 2);
  EXPECT_GT(team_return, lone_return + 20) << team_return << " vs " << lone_return;
}

TEST(TeamRollout, RowsAreEnvAgentPairsWithTheirOwnRewardsAndTheCriticSeesTheAgentId) {
  const int E = 3, N = 2, T = ProbeTeamTask::kSteps - 1;
  MultiAgentVecEnv env(std::make_unique<ProbeTeamTask>(E, N), 1, 5);
  env.ResetAll();
  torch::manual_seed(2);
  CriticInput critic(env.state_dim(), N, env.obs_dim(), true);
  ASSERT_EQ(critic.dim(), 2 + N + 3);
  ActorCritic net = MakeActorCritic(3, critic.dim(), 2, {8}, {8}, 0.5, 1e-3, {1.f, 1.f});
  control::ObsNormalizer norm(3);
  core::Rng rng(3);
  int episodes = 0;
  RolloutBuffer buf = CollectTeamRollout(env, net, norm, critic, rng, T, 0.9f,
                                         [&](const TeamEpisodeStats&) { ++episodes; });
  EXPECT_EQ(episodes, 0);
  ASSERT_EQ(buf.obs.sizes(), (std::vector<int64_t>{T, E * N, 3}));
  ASSERT_EQ(buf.critic_obs.sizes(), (std::vector<int64_t>{T, E * N, critic.dim()}));
  ASSERT_EQ(buf.act.sizes(), (std::vector<int64_t>{T, E * N, 2}));
  ASSERT_EQ(buf.reward.sizes(), (std::vector<int64_t>{T, E * N}));
  ASSERT_EQ(buf.last_value.sizes(), (std::vector<int64_t>{E * N}));
  for (int t = 0; t < T; ++t) {
    for (int r = 0; r < E * N; ++r) {
      const int a = r % N;
      EXPECT_FLOAT_EQ(buf.reward[t][r].item<float>(), buf.act[t][r][0].item<float>() + 100.f * a);
      for (int k = 0; k < N; ++k) {
        EXPECT_FLOAT_EQ(buf.critic_obs[t][r][2 + k].item<float>(), k == a ? 1.f : 0.f);
      }
    }
  }
  // the next step ends every episode: each agent's reward gets gamma V(terminal) of its row
  RolloutBuffer end = CollectTeamRollout(env, net, norm, critic, rng, 1, 0.9f,
                                         [&](const TeamEpisodeStats&) { ++episodes; });
  EXPECT_EQ(episodes, E);
  EXPECT_TRUE(torch::equal(end.done[0], torch::ones({E * N})));
  torch::NoGradGuard ng;
  auto view = [](const std::vector<float>& v, int64_t rows, int64_t cols) {
    return torch::from_blob(const_cast<float*>(v.data()), {rows, cols});
  };
  torch::Tensor terminal = critic.Build(view(env.terminal_state(), E, 2),
                                        norm.Normalize(view(env.terminal_obs(), E * N, 3)));
  torch::Tensor v = net.critic->forward(terminal).squeeze(-1);
  torch::Tensor paid = end.act[0].select(1, 0) + 100.f * torch::tensor({0.f, 1.f}).repeat({E});
  EXPECT_TRUE(torch::allclose(end.reward[0], paid + 0.9f * v));
  EXPECT_GT((0.9f * v).abs().min().item<float>(), 0.f);
}

MappoConfig ToyConfig() {
  MappoConfig c;
  c.num_envs = 32;
  c.num_agents = 2;
  c.threads = 1;
  c.seed = 7;
  c.rollout_steps = 50;
  c.epochs = 10;
  c.minibatches = 4;
  c.lr = 1e-3;
  c.gamma = 0.95;
  c.value_clip = 10;
  c.hidden = {64, 64};
  c.critic_hidden = {64, 64};
  c.total_steps = 400'000;
  c.checkpoint_every_s = 1e9;
  return c;
}

// the team learns: the mean agent return of the last 200 episodes rises clearly within 30
// iterations of 1600 team steps (a random team earns about 27 per 100-step episode)
TEST(Mappo, TeamCarryReturnRisesIntegration) {
  constexpr int kIterations = 30;
  constexpr double kMinGain = 12;  // per 100-step episode
  std::string dir = TempDir("learn");
  auto tr = MappoTrainer::Create(ToyConfig(), dir);
  ASSERT_TRUE(tr.ok()) << tr.status();
  double first = -1, last = 0;
  for (int k = 0; k < kIterations; ++k) {
    auto st = (*tr)->Iterate();
    ASSERT_TRUE(st.ok()) << st.status();
    if (first < 0 && st->episodes > 0) first = st->mean_return;
    last = st->mean_return;
    std::printf("iteration %d: %lld episodes, mean return %.2f, success %.2f\n", k + 1,
                static_cast<long long>(st->episodes), st->mean_return, st->success_rate);
  }
  EXPECT_GT(last, first + kMinGain) << "first " << first << " last " << last;
}

TEST(Mappo, SameSeedSameRunCheckpointResumesAndCorruptionIsAnError) {
  MappoConfig c = ToyConfig();
  c.num_envs = 4;
  c.rollout_steps = 30;
  c.epochs = 2;
  c.hidden = {16};
  c.critic_hidden = {16};
  c.total_steps = 4 * 4 * 30;
  std::string dir = TempDir("resume"), twin = TempDir("twin");
  {
    auto a = MappoTrainer::Create(c, dir);
    auto b = MappoTrainer::Create(c, twin);
    ASSERT_TRUE(a.ok() && b.ok()) << a.status() << b.status();
    for (int i = 0; i < 2; ++i) {
      auto sa = (*a)->Iterate();
      auto sb = (*b)->Iterate();
      ASSERT_TRUE(sa.ok() && sb.ok());
      EXPECT_EQ(sa->policy_loss, sb->policy_loss);
      EXPECT_EQ(sa->value_loss, sb->value_loss);
      EXPECT_EQ(sa->mean_return, sb->mean_return);
    }
    ASSERT_TRUE((*a)->Checkpoint().ok());
  }
  EXPECT_EQ(MappoTrainer::Create(c, dir).status().code(), absl::StatusCode::kAlreadyExists);
  auto r = MappoTrainer::Resume(dir);
  ASSERT_TRUE(r.ok()) << r.status();
  EXPECT_EQ((*r)->env_steps(), 2 * 4 * 30);
  EXPECT_EQ((*r)->config().num_agents, 2);
  while (!(*r)->done()) ASSERT_TRUE((*r)->Iterate().ok());
  // the shared actor is an ordinary policy file: each agent runs it on its own observation
  auto p = control::LoadPolicyFile(dir + "/policy.pt");
  ASSERT_TRUE(p.ok()) << p.status();
  EXPECT_EQ(p->meta.task, "team_carry");
  EXPECT_EQ(p->meta.obs_dim, 10);
  EXPECT_EQ(p->meta.act_dim, 2);
  fs::resize_file(dir + "/checkpoint.pt", fs::file_size(dir + "/checkpoint.pt") / 2);
  auto bad = MappoTrainer::Resume(dir);
  EXPECT_EQ(bad.status().code(), absl::StatusCode::kDataLoss) << bad.status();
  EXPECT_EQ(MappoTrainer::Resume(TempDir("none")).status().code(), absl::StatusCode::kNotFound);
  // a task of another team size than the config is refused
  auto wrong = MappoTrainer::CreateWithTask(c, TempDir("wrong"),
                                            std::make_unique<TeamCarryTask>(c.num_envs, 3));
  EXPECT_EQ(wrong.status().code(), absl::StatusCode::kInvalidArgument);
}

TEST(MappoConfig, StrictJsonNamesTheKeyAndWhatIsValid) {
  auto ok = MappoConfig::FromJson(nlohmann::json{{"lr", 1e-4}, {"num_agents", 3}});
  ASSERT_TRUE(ok.ok()) << ok.status();
  EXPECT_EQ(ok->num_agents, 3);
  auto round = MappoConfig::FromJson(ok->ToJson());
  ASSERT_TRUE(round.ok()) << round.status();
  EXPECT_EQ(round->ToJson(), ok->ToJson());
  auto unknown = MappoConfig::FromJson(nlohmann::json{{"learning_rate", 1e-4}});
  ASSERT_FALSE(unknown.ok());
  EXPECT_NE(unknown.status().message().find("learning_rate"), std::string::npos);
  EXPECT_NE(unknown.status().message().find("critic_agent_obs"), std::string::npos);
  auto range = MappoConfig::FromJson(nlohmann::json{{"gamma", 1.5}});
  ASSERT_FALSE(range.ok());
  EXPECT_NE(range.status().message().find("gamma"), std::string::npos) << range.status();
  auto frac = MappoConfig::FromJson(nlohmann::json{{"num_envs", 2.5}}, "/train");
  ASSERT_FALSE(frac.ok());
  EXPECT_NE(frac.status().message().find("/train/num_envs"), std::string::npos) << frac.status();
  auto task = MappoConfig::FromJson(nlohmann::json{{"task", "team_fly"}});
  ASSERT_FALSE(task.ok());
  EXPECT_NE(task.status().message().find("team_carry"), std::string::npos) << task.status();
  EXPECT_FALSE(MappoConfig::FromJson(nlohmann::json{{"hidden", {64, 0}}}).ok());
  EXPECT_FALSE(MappoConfig::FromJson(nlohmann::json{{"critic_agent_obs", 1}}).ok());
  EXPECT_FALSE(MappoConfig::FromJson(nlohmann::json{{"seed", -1}}).ok());
  EXPECT_FALSE(MakeMultiAgentTask("team_carry", 4, 1).ok());
  EXPECT_FALSE(MakeMultiAgentTask("team_fly", 4, 2).ok());
}

}  // namespace
}  // namespace simhuman::learn
