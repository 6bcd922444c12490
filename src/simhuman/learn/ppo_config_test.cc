#include "simhuman/learn/ppo_config.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <string>

namespace simhuman::learn {
namespace {

using nlohmann::json;
using ::testing::HasSubstr;

std::string Error(const json& j) {
  core::StatusOr<PpoConfig> c = PpoConfig::FromJson(j);
  return c.ok() ? std::string() : std::string(c.status().message());
}

TEST(PpoConfigTable, DefaultsRoundTripThroughToJsonWithEveryKey) {
  const PpoConfig defaults;
  json j = defaults.ToJson();
  // every key (38 before the table, + target_kl, body_scales, walk_gait, the walk reward's 3,
  // carry_grip, carry_held_start_frac, carry_put_down_start_frac, walk_route_share)
  EXPECT_EQ(j.size(), 48u);
  EXPECT_EQ(j["walk_gait"], "");
  EXPECT_EQ(j["carry_grip"], false);
  EXPECT_EQ(j["walk_gait_weight"], 1.0);
  EXPECT_EQ(j["body_scales"], json::array({1.0}));
  EXPECT_EQ(j["target_kl"], 0.0);
  EXPECT_TRUE(j["seed"].is_number_unsigned());
  EXPECT_TRUE(j["total_steps"].is_number_integer());
  auto back = PpoConfig::FromJson(json::parse(j.dump()));
  ASSERT_TRUE(back.ok()) << back.status();
  EXPECT_EQ(back->ToJson(), j);
  // missing keys keep the defaults; 3e7 is an integer
  auto partial = PpoConfig::FromJson(json{{"total_steps", 3e7}, {"hidden", {64, 64}}});
  ASSERT_TRUE(partial.ok()) << partial.status();
  EXPECT_EQ(partial->total_steps, 30'000'000);
  EXPECT_EQ(partial->hidden, (std::vector<int>{64, 64}));
  EXPECT_EQ(partial->num_envs, defaults.num_envs);
  EXPECT_EQ(partial->critic_hidden, defaults.critic_hidden);
  // the whole uint64 range of seeds, exactly
  auto seed = PpoConfig::FromJson(json::parse("{\"seed\": 18446744073709551615}"));
  ASSERT_TRUE(seed.ok()) << seed.status();
  EXPECT_EQ(seed->seed, 18446744073709551615u);
}

TEST(PpoConfigTable, ErrorsNameTheKeyTheValueAndWhatIsValid) {
  EXPECT_THAT(Error(json{{"learning_rate", 1e-4}}),
              HasSubstr("unknown key 'learning_rate'; valid keys are: task, total_steps"));
  EXPECT_EQ(Error(json{{"num_envs", 5000}}),
            "training config 'num_envs' = 5000 is invalid; valid range is [1, 4096]");
  EXPECT_EQ(Error(json{{"gamma", 0}}),
            "training config 'gamma' = 0 is invalid; valid range is (0, 1]");
  EXPECT_EQ(Error(json{{"body_scales", {0.6, 2}}}),
            "training config 'body_scales' = [0.6, 2] is invalid; entry 1 (2) is outside the "
            "valid range [0.5, 1.5]");
  EXPECT_THAT(Error(json{{"body_scales", json::array()}}), HasSubstr("at least 1 entry"));
  EXPECT_EQ(Error(json{{"task", "carry"}, {"carry_held_start_frac", 1.5}}),
            "training config 'carry_held_start_frac' = 1.5 is invalid; valid range is [0, 1]");
  EXPECT_THAT(Error(json{{"task", "walk"}, {"carry_held_start_frac", 0.5}}),
              HasSubstr("carry_held_start_frac applies to the carry task only; task is 'walk'"));
  EXPECT_EQ(Error(json{{"task", "carry"}, {"carry_put_down_start_frac", -0.1}}),
            "training config 'carry_put_down_start_frac' = -0.1 is invalid; valid range is [0, 1]");
  EXPECT_THAT(
      Error(json{{"task", "walk"}, {"carry_put_down_start_frac", 0.2}}),
      HasSubstr("carry_put_down_start_frac applies to the carry task only; task is 'walk'"));
  EXPECT_TRUE(Error(json{{"task", "carry"}, {"carry_put_down_start_frac", 0.25}}).empty());
  EXPECT_THAT(Error(json{{"walk_gait_width", 0}}),
              HasSubstr("training config 'walk_gait_width' = 0 is invalid; valid range is (0"));
  EXPECT_THAT(Error(json{{"task", "grasp"}, {"walk_foot_slip_weight", 2}}),
              HasSubstr("apply to the walk task only; task is 'grasp'"));
  EXPECT_THAT(Error(json{{"task", "carry"}, {"walk_route_share", 0.5}}),
              HasSubstr("walk_route_share apply to the walk task only; task is 'carry'"));
  EXPECT_EQ(Error(json{{"walk_route_share", 1.5}}),
            "training config 'walk_route_share' = 1.5 is invalid; valid range is [0, 1]");
  EXPECT_TRUE(Error(json{{"task", "walk"}, {"walk_route_share", 0.5}}).empty());
  EXPECT_THAT(Error(json{{"body_scales", {1, "big"}}}), HasSubstr("/body_scales/1"));
  EXPECT_THAT(Error(json{{"body_scales", {0.8, 1.0}}, {"amp_clips", {"a.bvh"}}}),
              HasSubstr("body_scales other than [1] cannot be combined with amp_clips"));
  EXPECT_EQ(Error(json{{"task", "carry"}, {"body_scales", {0.8, 1.0}}}),
            "training config: body_scales other than [1] apply to the walk task only; task is "
            "'carry'");
  EXPECT_EQ(Error(json{{"task", "fly"}}),
            "training config 'task' = \"fly\" is invalid; valid values are: walk, reach, carry, "
            "carry-lift, carry-deliver, grasp, grasp-residual, place");
  EXPECT_EQ(Error(json{{"hidden", json::array()}}),
            "training config 'hidden' = [] is invalid; it needs at least 1 entry");
  EXPECT_THAT(Error(json{{"amp_disc_hidden", {256, -1}}}),
              HasSubstr("'amp_disc_hidden' = [256, -1] is invalid; entry 1 (-1) is outside"));
  EXPECT_THAT(
      Error(json{{"amp_clips", {"a.bvh", ""}}}),
      HasSubstr("'amp_clips' = [\"a.bvh\", \"\"] is invalid; entry 1: it must not be empty"));
  // types: the pointer and what was expected
  EXPECT_EQ(Error(json{{"lr", "fast"}}), "/lr: expected a number, got string");
  EXPECT_EQ(Error(json{{"num_envs", 64.5}}), "/num_envs: expected an integer, got 64.5");
  EXPECT_EQ(Error(json{{"epochs", true}}), "/epochs: expected an integer, got boolean");
  EXPECT_THAT(Error(json{{"seed", -1}}), HasSubstr("/seed: expected an integer in [0, "));
  EXPECT_EQ(Error(json{{"critic_hidden", {64, "x"}}}),
            "/critic_hidden/1: expected an integer, got string");
  EXPECT_EQ(Error(json::array()), "/: expected a JSON object, got array");
}

TEST(PpoConfigTable, AResumedRunChangesOnlyItsScheduleKeys) {
  PpoConfig stored;
  stored.task = "carry";
  stored.hidden = {256, 128};
  const json j = stored.ToJson();
  auto changed = PpoConfig::WithResumeChanges(j, json{{"curriculum_max_steps", 1500000}});
  ASSERT_TRUE(changed.ok()) << changed.status();
  EXPECT_EQ(changed->curriculum_max_steps, 1'500'000);
  EXPECT_EQ(changed->hidden, stored.hidden);
  EXPECT_EQ(changed->task, "carry");
  // the networks, the task and the envs stay: the key is named with those that may change
  for (const json& bad : {json{{"hidden", {64}}}, json{{"task", "walk"}}, json{{"num_envs", 8}}}) {
    auto r = PpoConfig::WithResumeChanges(j, bad);
    ASSERT_FALSE(r.ok()) << bad.dump();
    EXPECT_THAT(std::string(r.status().message()), HasSubstr("cannot change in a resumed run"));
    EXPECT_THAT(std::string(r.status().message()), HasSubstr("valid: curriculum_max_steps, lr"));
  }
  // a value out of range is the table's error
  auto negative = PpoConfig::WithResumeChanges(j, json{{"lr", -1.0}});
  ASSERT_FALSE(negative.ok());
  EXPECT_THAT(std::string(negative.status().message()), HasSubstr("'lr' = -1 is invalid"));
  EXPECT_FALSE(PpoConfig::WithResumeChanges(j, json::array({1})).ok());
}

TEST(PpoConfigTable, CrossFieldChecksFollowTheTable) {
  EXPECT_THAT(Error(json{{"num_envs", 4}, {"rollout_chunks", 5}}),
              HasSubstr("'rollout_chunks' = 5 is invalid; it must not exceed num_envs (4)"));
  EXPECT_TRUE(Error(json{{"num_envs", 4}, {"rollout_chunks", 4}}).empty());
  EXPECT_THAT(Error(json{{"num_envs", 1}, {"rollout_steps", 2}, {"minibatches", 3}}),
              HasSubstr("num_envs x rollout_steps (1 x 2) must be at least minibatches (3)"));
  EXPECT_THAT(Error(json{{"amp_disc_batch", 10}, {"amp_replay_size", 9}}),
              HasSubstr("'amp_replay_size' = 9 is invalid; it must be at least amp_disc_batch"));
  EXPECT_THAT(Error(json{{"physics_solver", "pgs"}, {"task", "reach"}}),
              HasSubstr("applies to the walk task only"));
  // Validate() checks a struct built in code the same way
  PpoConfig c;
  c.threads = 0;
  EXPECT_EQ(std::string(c.Validate().message()),
            "training config 'threads' = 0 is invalid; valid range is [1, 64]");
}

}  // namespace
}  // namespace simhuman::learn
