// Unit tests of the PPO stages shared by PpoTrainer and MappoTrainer: GAE with time-limit
// bootstraps, the PPO update, the non-finite guard and the episode window.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "simhuman/learn/gae.h"
#include "simhuman/learn/ppo_rollout.h"
#include "simhuman/learn/ppo_update.h"

namespace simhuman::learn {
namespace {

constexpr float kTol = 1e-5f;

torch::Tensor Col(const std::vector<float>& v) {
  return torch::tensor(v).reshape({static_cast<int64_t>(v.size()), 1});
}

TEST(Gae, LambdaOneIsTheDiscountedReturnMinusTheValue) {
  const float gamma = 0.9f;
  torch::Tensor rew = Col({1, 2, 3}), val = Col({0.5f, -1, 2}), done = Col({0, 0, 0});
  torch::Tensor last = torch::tensor({4.f});
  torch::Tensor adv = ComputeGae(rew, val, done, last, gamma, 1.f);
  ASSERT_EQ(adv.sizes(), rew.sizes());
  const float g0 = 1 + gamma * 2 + gamma * gamma * 3 + gamma * gamma * gamma * 4;
  const float g1 = 2 + gamma * 3 + gamma * gamma * 4;
  const float g2 = 3 + gamma * 4;
  EXPECT_NEAR(adv[0][0].item<float>(), g0 - 0.5f, kTol);
  EXPECT_NEAR(adv[1][0].item<float>(), g1 + 1, kTol);
  EXPECT_NEAR(adv[2][0].item<float>(), g2 - 2, kTol);
}

TEST(Gae, LambdaZeroIsTheOneStepErrorAndADoneCutsTheChain) {
  const float gamma = 0.5f;
  // two rows: row 0 ends at step 1, row 1 never ends
  torch::Tensor rew = torch::tensor({1.f, 1.f, 1.f, 1.f, 1.f, 1.f}).reshape({3, 2});
  torch::Tensor val = torch::tensor({2.f, 2.f, 3.f, 3.f, 5.f, 5.f}).reshape({3, 2});
  torch::Tensor done = torch::tensor({0.f, 0.f, 1.f, 0.f, 0.f, 0.f}).reshape({3, 2});
  torch::Tensor last = torch::tensor({7.f, 7.f});
  torch::Tensor td = ComputeGae(rew, val, done, last, gamma, 0.f);
  EXPECT_NEAR(td[0][0].item<float>(), 1 + gamma * 3 - 2, kTol);
  EXPECT_NEAR(td[1][0].item<float>(), 1 - 3, kTol);  // ended: no next value
  EXPECT_NEAR(td[1][1].item<float>(), 1 + gamma * 5 - 3, kTol);
  EXPECT_NEAR(td[2][1].item<float>(), 1 + gamma * 7 - 5, kTol);
  // with lambda 1 row 0's first advantage still stops at the done
  torch::Tensor mc = ComputeGae(rew, val, done, last, gamma, 1.f);
  EXPECT_NEAR(mc[0][0].item<float>(), 1 + gamma * 1 - 2, kTol);
  EXPECT_NEAR(mc[0][1].item<float>(), 1 + gamma * (1 + gamma * (1 + gamma * 7)) - 2, kTol);
}

TEST(Gae, TimeLimitBootstrapAddsTheDiscountedValueToTruncatedRowsOnly) {
  torch::Tensor rew = torch::tensor({1.f, 1.f, 1.f, 1.f});
  AddTimeLimitBootstrap(rew, {1, 3}, torch::tensor({10.f, -2.f}), 0.5f);
  EXPECT_FLOAT_EQ(rew[0].item<float>(), 1);
  EXPECT_FLOAT_EQ(rew[1].item<float>(), 6);
  EXPECT_FLOAT_EQ(rew[2].item<float>(), 1);
  EXPECT_FLOAT_EQ(rew[3].item<float>(), 0);
  AddTimeLimitBootstrap(rew, {}, torch::Tensor(), 0.5f);
  EXPECT_FLOAT_EQ(rew[1].item<float>(), 6);
}

TEST(EpisodeWindow, KeepsTheLastEpisodesAndAveragesThem) {
  EpisodeWindow w(2);
  EXPECT_EQ(w.Means().ret, 0);
  w.Add(EpisodeStats{100, 10, false, true});
  w.Add(EpisodeStats{1, 2, true, false});
  w.Add(EpisodeStats{3, 4, true, true});
  EXPECT_EQ(w.size(), 2u);
  EpisodeMeans m = w.Means();
  EXPECT_DOUBLE_EQ(m.ret, 2);
  EXPECT_DOUBLE_EQ(m.length, 3);
  EXPECT_DOUBLE_EQ(m.success, 1);
  EXPECT_DOUBLE_EQ(m.fall, 0.5);
}

// a one-step bandit: action 1 earns advantage +1, action -1 earns -1, returns 3; the rollout
// policy is `net` as it is now
PpoBatch BanditBatch(ActorCritic& net) {
  const int64_t n = 64;
  PpoBatch b;
  b.obs = torch::ones({n, 3});
  b.critic_obs = torch::ones({n, 2});
  b.act = torch::cat({torch::ones({n / 2, 1}), -torch::ones({n / 2, 1})});
  torch::NoGradGuard ng;
  b.old_logp =
      GaussianLogProb(b.act, net.actor->forward(b.obs), net.actor->log_std(), net.act_used);
  b.old_value = net.critic->forward(b.critic_obs).squeeze(-1);
  b.adv = torch::cat({torch::ones({n / 2}), -torch::ones({n / 2})});
  b.ret = torch::full({n}, 3.f);
  return b;
}

// PPO moves the mean toward +1 and the value toward the returns
TEST(PpoUpdate, MovesTheMeanTowardPositiveAdvantages) {
  torch::manual_seed(4);
  ActorCritic net = MakeActorCritic(3, 2, 1, {16}, {}, 0.5, 1e-2, {1.f});
  PpoBatch b = BanditBatch(net);
  torch::Tensor mean0;
  {
    torch::NoGradGuard ng;
    mean0 = net.actor->forward(b.obs[0].unsqueeze(0)).squeeze();
  }
  PpoUpdateOptions o;
  o.epochs = 4;
  core::Rng rng(1);
  PpoUpdateStats st = PpoUpdate(net, b, o, rng);
  EXPECT_TRUE(st.rollout_finite);
  EXPECT_EQ(st.minibatches, o.epochs * o.minibatches);
  EXPECT_EQ(st.skipped, 0);
  torch::NoGradGuard ng;
  EXPECT_GT(net.actor->forward(b.obs[0].unsqueeze(0)).squeeze().item<float>(), mean0.item<float>());
  float v = net.critic->forward(b.critic_obs[0].unsqueeze(0)).squeeze().item<float>();
  EXPECT_GT(v, b.old_value[0].item<float>());
}

// the first minibatch steps from the rollout policy (KL 0); the second sees the step's KL
TEST(PpoUpdate, TargetKlEndsTheEpochsEarly) {
  for (double target : {1e-7, 1e3}) {
    torch::manual_seed(4);
    ActorCritic net = MakeActorCritic(3, 2, 1, {16}, {}, 0.5, 1e-2, {1.f});
    PpoBatch b = BanditBatch(net);
    PpoUpdateOptions o;
    o.epochs = 4;
    o.target_kl = target;
    core::Rng rng(1);
    PpoUpdateStats st = PpoUpdate(net, b, o, rng);
    if (target < 1) {
      EXPECT_TRUE(st.kl_stopped);
      EXPECT_EQ(st.minibatches, 2);
    } else {
      EXPECT_FALSE(st.kl_stopped);
      EXPECT_EQ(st.minibatches, o.epochs * o.minibatches);
    }
  }
}

TEST(PpoUpdate, NonFiniteRolloutTrainsNothingAndTheGuardAbortsAfterSeveral) {
  torch::manual_seed(5);
  ActorCritic net = MakeActorCritic(2, 2, 1, {8}, {}, 0.5, 1e-2, {1.f});
  PpoBatch b;
  b.obs = torch::ones({8, 2});
  b.act = torch::zeros({8, 1});
  b.old_logp = torch::zeros({8});
  b.old_value = torch::zeros({8});
  b.ret = torch::full({8}, NAN);
  b.adv = torch::ones({8});
  PpoUpdateOptions o;
  o.epochs = 2;
  o.minibatches = 2;
  core::Rng rng(1);
  NonFiniteGuard guard(2);
  std::vector<torch::Tensor> before;
  for (const auto& p : net.Params()) before.push_back(p.detach().clone());
  guard.Begin(net.Params());
  PpoUpdateStats st = PpoUpdate(net, b, o, rng);
  EXPECT_FALSE(st.rollout_finite);
  EXPECT_EQ(st.skipped, 4);
  EXPECT_TRUE(guard.End(st, 0).ok());
  EXPECT_EQ(guard.bad_in_row(), 1);
  for (size_t k = 0; k < before.size(); ++k) EXPECT_TRUE(torch::equal(before[k], net.Params()[k]));
  // weights that turned non-finite are restored
  guard.Begin(net.Params());
  {
    torch::NoGradGuard ng;
    net.Params()[0].fill_(NAN);
  }
  absl::Status s = guard.End(PpoUpdateStats(), 7);
  EXPECT_EQ(s.code(), absl::StatusCode::kInternal);
  EXPECT_NE(s.message().find("iteration 7"), std::string::npos) << s;
  EXPECT_TRUE(torch::equal(before[0], net.Params()[0]));
  // a clean update resets the count
  guard.Begin(net.Params());
  EXPECT_TRUE(guard.End(PpoUpdateStats(), 8).ok());
  EXPECT_EQ(guard.bad_in_row(), 0);
}

}  // namespace
}  // namespace simhuman::learn
