#include "simhuman/learn/place_env.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "simhuman/learn/vec_env.h"

namespace simhuman::learn {
namespace {

TEST(PlaceEnvTest, TheRewardFollowsSuccessDistanceAndUprightness) {
  EXPECT_FLOAT_EQ(PlaceEpisodeReward(true, 0, 1), 4.0f);
  EXPECT_FLOAT_EQ(PlaceEpisodeReward(false, 0, 1), 2.0f);
  EXPECT_NEAR(PlaceEpisodeReward(false, 0.03, 1), 1 + std::exp(-1.0), 1e-6);
  EXPECT_NEAR(PlaceEpisodeReward(false, 1.0, std::cos(M_PI / 6)), 0, 1e-6);  // 30 degrees
  EXPECT_NEAR(PlaceEpisodeReward(false, 1.0, 0), 0, 1e-6);                   // lying
  EXPECT_FALSE(PlaceTask::Create(0).ok());
}

// episodes start where placing begins (the held object above its target) and end after a few
// decisions with the reward of how the object was left; a reset mid-episode drops it
TEST(PlaceEnvTest, EpisodesStartWherePlacingBeginsAndEndWithTheOutcomeIntegration) {
  auto made = PlaceTask::Create(2);
  ASSERT_TRUE(made.ok()) << made.status();
  PlaceTask& task = **made;
  EXPECT_EQ(task.obs_dim(), control::manip::kPlaceObsDim);
  EXPECT_EQ(task.act_dim(), control::manip::kPlaceActDim);
  std::vector<float> obs(task.obs_dim()), act(task.act_dim(), 0.0f);
  int episodes = 0, successes = 0;
  for (int ep = 0; ep < 6; ++ep) {
    task.Reset(0, 40 + ep, obs.data());
    for (float v : obs) ASSERT_TRUE(std::isfinite(v));
    // obs[3]: the object's base above the target; obs[4..6]: its up axis
    EXPECT_GT(obs[3], 0.02) << "episode " << ep;
    EXPECT_LT(obs[3], 0.15) << "episode " << ep;
    EXPECT_GT(obs[6], 0.8) << "episode " << ep;
    StepInfo info;
    int decisions = 0;
    do {
      task.Step(0, act.data(), obs.data(), &info);
      ++decisions;
      ASSERT_LE(decisions, 5);  // 10 cm of descent in 3 cm segments: 4 at most
    } while (!info.terminated);
    EXPECT_FALSE(info.truncated);
    EXPECT_GE(info.reward, 0);
    EXPECT_LE(info.reward, 4);
    EXPECT_EQ(info.success, info.reward >= 2) << info.reward;
    ++episodes;
    successes += info.success;
  }
  // six episodes from the first scene that reaches placing: the scripted placing (zero actions)
  // is deterministic, so all six end alike
  EXPECT_GE(task.scenes_run(0), 1);
  EXPECT_TRUE(successes == 0 || successes == episodes) << successes;

  // env 1: reset while an episode waits for its action, then a whole episode
  task.Reset(1, 7, obs.data());
  task.Reset(1, 8, obs.data());
  StepInfo info;
  for (int k = 0; k < 5 && !info.terminated; ++k) task.Step(1, act.data(), obs.data(), &info);
  EXPECT_TRUE(info.terminated);
}

// the task trains through VecEnv's automatic resets (threads of its own under the worker pool)
TEST(PlaceEnvTest, VecEnvStepsThePlaceTaskIntegration) {
  auto made = PlaceTask::Create(3);
  ASSERT_TRUE(made.ok()) << made.status();
  VecEnv env(std::move(*made), 2, 5);
  env.ResetAll();
  std::vector<float> actions(3 * control::manip::kPlaceActDim, 0.0f);
  int finished = 0;
  for (int k = 0; k < 6; ++k) {
    env.Step(actions.data());
    finished += static_cast<int>(env.finished().size());
  }
  EXPECT_GE(finished, 3);
}

}  // namespace
}  // namespace simhuman::learn
