#include "simhuman/learn/carry_eval.h"

#include <gtest/gtest.h>

#include <memory>
#include <string>

#include "simhuman/control/policy/policy_net.h"
#include "simhuman/core/testing_temp.h"
#include "simhuman/learn/ppo.h"

namespace simhuman::learn {
namespace {

const std::string kWalk = std::string(SIMHUMAN_SOURCE_DIR) + "/assets/policies/walk.pt";

// the policy file of a carry run checkpointed before any update, in the shipped walker's gait
// (its weights from the walker with `from_walker`, untrained otherwise)
core::StatusOr<std::string> FreshCarryPolicy(const std::string& name, bool from_walker,
                                             const std::string& task = "carry") {
  PpoConfig cfg;
  cfg.task = task;
  cfg.num_envs = 1;
  cfg.threads = 1;
  if (from_walker) {
    cfg.hidden = {256, 128};
    cfg.init_from = kWalk;
  }
  SH_ASSIGN_OR_RETURN(control::LoadedPolicy walker, control::LoadPolicyFile(kWalk));
  cfg.walk_gait = walker.meta.variant;
  const std::string dir = core::testing::UniqueTempPath(name);
  SH_ASSIGN_OR_RETURN(std::unique_ptr<PpoTrainer> tr, PpoTrainer::Create(cfg, dir));
  SH_RETURN_IF_ERROR(tr->Checkpoint());
  return dir + "/policy.pt";
}

// options for a few short episodes (boxes at most 2 m away, 8 s plus the walking time) of `policy`
CarryEvalOptions ShortRun(const std::string& policy, int episodes) {
  CarryEvalOptions o;
  o.policy = policy;
  o.episodes = episodes;
  o.base_time_s = 8;
  o.max_dist_m = 2;
  return o;
}

TEST(CarryEval, RefusesAPolicyOfAnotherTaskAndBadRanges) {
  CarryEvalOptions o;
  o.policy = kWalk;
  o.episodes = 1;
  auto s = RunCarryEval(o, nullptr);
  ASSERT_FALSE(s.ok());
  EXPECT_NE(s.status().message().find("'walk' policy"), std::string::npos) << s.status();
  EXPECT_NE(s.status().message().find("train --task carry"), std::string::npos) << s.status();
  o.min_dist_m = 30;
  s = RunCarryEval(o, nullptr);
  ASSERT_FALSE(s.ok());
  EXPECT_NE(s.status().message().find("distance"), std::string::npos) << s.status();
  o.min_dist_m = 1;
  o.policy = "/nonexistent/carry.pt";
  EXPECT_FALSE(RunCarryEval(o, nullptr).ok());
}

// a carry run with gripping hands records it in its policy file, and the suite evaluates such
// a policy with the grip; other tasks refuse the key
TEST(CarryEval, GripIsRecordedInThePolicyFileIntegration) {
  PpoConfig cfg;
  cfg.task = "carry";
  cfg.num_envs = 1;
  cfg.threads = 1;
  cfg.carry_grip = true;
  const std::string dir = core::testing::UniqueTempPath("carry_grip");
  auto tr = PpoTrainer::Create(cfg, dir);
  ASSERT_TRUE(tr.ok()) << tr.status();
  ASSERT_TRUE((*tr)->Checkpoint().ok());
  auto p = control::LoadPolicyFile(dir + "/policy.pt");
  ASSERT_TRUE(p.ok()) << p.status();
  EXPECT_TRUE(p->meta.carry_grip);
  CarryEvalOptions o;
  o.policy = dir + "/policy.pt";
  o.episodes = 1;
  o.base_time_s = 1;
  o.max_dist_m = 2;
  EXPECT_TRUE(RunCarryEval(o, nullptr).ok());
  PpoConfig walk;
  walk.carry_grip = true;
  EXPECT_NE(std::string(walk.Validate().message()).find("carry_grip applies to the carry task"),
            std::string::npos)
      << walk.Validate();
}

// a carry policy fresh from the walking one: episodes run to an end, are drawn from the
// protocol's ranges, reproducible by seed, and summarised per mass bin
TEST(CarryEval, EpisodesFollowTheProtocolAndRepeatBySeed) {
  auto policy = FreshCarryPolicy("carry_eval", true);
  ASSERT_TRUE(policy.ok()) << policy.status();
  CarryEvalOptions o;
  o.policy = *policy;
  o.episodes = 2;
  o.base_time_s = 3;  // short episodes: only the bookkeeping is under test
  o.max_dist_m = 2;
  std::vector<CarryEpisode> a, b;
  auto s = RunCarryEval(o, &a);
  ASSERT_TRUE(s.ok()) << s.status();
  ASSERT_TRUE(RunCarryEval(o, &b).ok());
  ASSERT_EQ(a.size(), 2u);
  int binned = 0;
  for (int n : s->mass_bin_episodes) binned += n;
  EXPECT_EQ(binned, 2);
  for (size_t i = 0; i < a.size(); ++i) {
    EXPECT_GE(a[i].mass_kg, 2.0);
    EXPECT_LE(a[i].mass_kg, 13.0);
    EXPECT_GE(a[i].side_m, 0.25);
    EXPECT_LE(a[i].side_m, 0.75);
    EXPECT_GE(a[i].dist_m, 1.0);
    EXPECT_LE(a[i].dist_m, 2.0);
    EXPECT_FALSE(a[i].end_reason.empty());
    EXPECT_DOUBLE_EQ(a[i].final_dist_m, b[i].final_dist_m);
    EXPECT_EQ(a[i].end_reason, b[i].end_reason);
    EXPECT_LE(a[i].time_s, 3 + 2.5 * a[i].dist_m + 0.1);
  }
  EXPECT_EQ(CarrySummaryJson(*s, o)["success_by_mass"].size(), 4u);
}

// --approach-policy: a walking policy walks up to the box and the carry policy takes over at the
// lift. An untrained carry policy (no --init-from) falls on its way to the box; with the walker
// walking up, the same episodes get past the approach. A policy of another task, or a walker of
// another gait, is refused by name.
TEST(CarryEval, AnApproachPolicyWalksUpToTheBoxIntegration) {
  auto policy = FreshCarryPolicy("carry_approach", false);
  ASSERT_TRUE(policy.ok()) << policy.status();
  CarryEvalOptions o = ShortRun(*policy, 3);
  std::vector<CarryEpisode> alone, walked;
  ASSERT_TRUE(RunCarryEval(o, &alone).ok());
  o.approach_policy = kWalk;
  auto s = RunCarryEval(o, &walked);
  ASSERT_TRUE(s.ok()) << s.status();
  EXPECT_EQ(CarrySummaryJson(*s, o)["approach_policy"], kWalk);
  int fell_walking_up_alone = 0, past_the_approach = 0;
  for (size_t i = 0; i < alone.size(); ++i) {
    fell_walking_up_alone += alone[i].fell && alone[i].last_phase == "approach";
    past_the_approach += walked[i].last_phase != "approach";
  }
  EXPECT_EQ(fell_walking_up_alone, 3);
  EXPECT_GE(past_the_approach, 2);
  o.approach_policy = o.policy;  // a carry policy
  auto bad = RunCarryEval(o, nullptr);
  ASSERT_FALSE(bad.ok());
  EXPECT_NE(bad.status().message().find("needs a 'walk' policy"), std::string::npos)
      << bad.status();
}

// The phase policies (--walker, --lift-policy, --deliver-policy) are each checked for their
// task by flag, and a chain of them runs: the walker walks up (every episode gets past the
// approach, where the untrained carry policy alone falls), the lift policy lifts; the summary
// names them.
TEST(CarryEval, AChainOfPhasePoliciesRunsAndEachIsCheckedIntegration) {
  auto carry = FreshCarryPolicy("carry_chain", false);
  ASSERT_TRUE(carry.ok()) << carry.status();
  auto lift = FreshCarryPolicy("carry_chain_lift", false, "carry-lift");
  ASSERT_TRUE(lift.ok()) << lift.status();
  CarryEvalOptions o = ShortRun(*carry, 3);
  o.walker = *carry;  // a carry policy as the walker
  auto bad = RunCarryEval(o, nullptr);
  ASSERT_FALSE(bad.ok());
  EXPECT_NE(bad.status().message().find("--walker"), std::string::npos) << bad.status();
  EXPECT_NE(bad.status().message().find("needs a 'walk' policy"), std::string::npos);
  o.walker = kWalk;
  o.lift_policy = *carry;  // a whole-carry policy as the lift policy
  bad = RunCarryEval(o, nullptr);
  ASSERT_FALSE(bad.ok());
  EXPECT_NE(bad.status().message().find("--lift-policy"), std::string::npos) << bad.status();
  EXPECT_NE(bad.status().message().find("needs a 'carry-lift' policy"), std::string::npos);
  o.lift_policy = *lift;
  o.deliver_policy = *lift;  // a lift policy as the delivery policy
  bad = RunCarryEval(o, nullptr);
  ASSERT_FALSE(bad.ok());
  EXPECT_NE(bad.status().message().find("--deliver-policy"), std::string::npos) << bad.status();
  o.deliver_policy.clear();
  std::vector<CarryEpisode> eps;
  auto s = RunCarryEval(o, &eps);
  ASSERT_TRUE(s.ok()) << s.status();
  EXPECT_EQ(CarrySummaryJson(*s, o)["walker"], kWalk);
  EXPECT_EQ(CarrySummaryJson(*s, o)["lift_policy"], *lift);
  int past_the_approach = 0;
  for (const CarryEpisode& e : eps) past_the_approach += e.last_phase != "approach";
  EXPECT_EQ(past_the_approach, 3);
}

// --model-squats: the model-based lift and put-down replace the policies there; a lift or
// delivery policy given as well is an error naming both flags
TEST(CarryEval, ModelSquatsReplaceTheSquatPoliciesIntegration) {
  auto carry = FreshCarryPolicy("carry_model_squats", false);
  ASSERT_TRUE(carry.ok()) << carry.status();
  CarryEvalOptions o = ShortRun(*carry, 2);
  o.walker = kWalk;
  o.model_squats = true;
  o.deliver_policy = *carry;
  auto bad = RunCarryEval(o, nullptr);
  ASSERT_FALSE(bad.ok());
  EXPECT_NE(bad.status().message().find("--model-squats and --deliver-policy"), std::string::npos)
      << bad.status();
  o.deliver_policy.clear();
  std::vector<CarryEpisode> eps;
  auto s = RunCarryEval(o, &eps);
  ASSERT_TRUE(s.ok()) << s.status();
  EXPECT_EQ(CarrySummaryJson(*s, o)["model_squats"], true);
  int past_the_approach = 0;
  for (const CarryEpisode& e : eps) past_the_approach += e.last_phase != "approach";
  EXPECT_EQ(past_the_approach, 2);
}

}  // namespace
}  // namespace simhuman::learn
