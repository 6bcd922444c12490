#include "simhuman/learn/grasp_env.h"

#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <vector>

#include "simhuman/core/rng.h"

namespace simhuman::learn {
namespace {

TEST(GraspEnvTest, EpisodesStartBesideTheObjectAndRunTheirLengthIntegration) {
  auto t = GraspTask::Create(2);
  ASSERT_TRUE(t.ok()) << t.status();
  GraspTask& task = **t;
  EXPECT_EQ(task.obs_dim(), control::manip::kGraspObsDim);
  EXPECT_EQ(task.act_dim(), 29);
  std::vector<float> obs(task.obs_dim()), act(task.act_dim());
  core::Rng rng(3);
  int starts_near = 0;
  for (int ep = 0; ep < 4; ++ep) {
    task.Reset(0, 100 + ep, obs.data());
    const GraspProblem& p = task.problem(0);
    EXPECT_GE(p.mass_kg, 1.0);
    EXPECT_LE(p.mass_kg, 5.0);
    EXPECT_LE((p.actual_pos - p.planned_pos).norm(), 0.03);
    // the palm starts within a hand's reach of the object, not inside it
    const Eigen::Vector3d palm(task.data(0)->site_xpos + 3 * task.index().arm.palm_site);
    const double d = (palm - p.actual_pos).head<2>().norm();
    starts_near += d < 0.15;
    EXPECT_FALSE(task.Dropped(0) && d < 0.15);
    StepInfo info;
    int steps = 0;
    do {
      for (float& a : act) a = static_cast<float>(rng.Uniform(-1, 1));
      task.Step(0, act.data(), obs.data(), &info);
      ++steps;
      for (float v : obs) ASSERT_TRUE(std::isfinite(v));
    } while (!info.truncated && !info.terminated);
    EXPECT_EQ(steps, GraspTask::kMaxSteps);
    EXPECT_FALSE(info.terminated);
  }
  EXPECT_GE(starts_near, 3);
}

// closing the hand with no arm motion beats flailing at random on the reward (the reward
// points somewhere); a sanity check of the terms' signs
TEST(GraspEnvTest, ClosingTheHandEarnsMoreThanOpeningIt) {
  auto t = GraspTask::Create(1);
  ASSERT_TRUE(t.ok()) << t.status();
  GraspTask& task = **t;
  std::vector<float> obs(task.obs_dim()), act(task.act_dim());
  auto run = [&](float finger) {
    task.Reset(0, 7, obs.data());
    StepInfo info;
    double ret = 0;
    for (int k = 0; k < 30; ++k) {
      // the arm still, the four fingers flexing (or extending); the thumb keeps its C
      for (int j = 0; j < task.act_dim(); ++j) act[j] = j < 7 || j >= 7 + 17 ? 0.0f : finger;
      task.Step(0, act.data(), obs.data(), &info);
      ret += info.reward;
    }
    return ret;
  };
  EXPECT_GT(run(0.6f), run(-0.6f));
}

// the residual task adds the policy's action to the scripted grasp's: with a zero action its
// hand closes on the object (the scripted grasp), while the plain task's hand stays open
TEST(GraspEnvTest, AZeroResidualRunsTheScriptedGraspIntegration) {
  auto plain = GraspTask::Create(1);
  auto residual = GraspTask::Create(1, /*residual=*/true);
  ASSERT_TRUE(plain.ok() && residual.ok());
  EXPECT_EQ((*residual)->name(), "grasp-residual");
  auto flexion = [](GraspTask& task) {
    std::vector<float> obs(task.obs_dim()), act(task.act_dim(), 0.0f);
    task.Reset(0, 11, obs.data());
    StepInfo info;
    for (int k = 0; k < GraspTask::kGraspSteps; ++k) task.Step(0, act.data(), obs.data(), &info);
    // the four fingers' MCP flexion (after the arm's 7, the palm arch and each abduction)
    double sum = 0;
    for (int f = 0; f < 4; ++f) {
      sum += task.data(0)->qpos[task.index().qpos[control::manip::ArmChain::kDofs + 2 + 4 * f]];
    }
    return sum / 4;
  };
  EXPECT_LT(std::abs(flexion(**plain)), 0.05);
  EXPECT_GT(flexion(**residual), 0.3);
}

}  // namespace
}  // namespace simhuman::learn
