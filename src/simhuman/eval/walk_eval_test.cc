#include "simhuman/eval/walk_eval.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

namespace simhuman::eval {
namespace {

TEST(WalkEvalJson, EpisodeAndSummaryCarryTheDocumentedFields) {
  WalkEpisode e;
  e.index = 7;
  e.dist_m = 3.5;
  e.success = true;
  e.final_dist_m = 0.11;
  nlohmann::ordered_json j = WalkEpisodeJson(e);
  EXPECT_EQ(j["episode"], 7);
  EXPECT_EQ(j["success"], true);
  EXPECT_DOUBLE_EQ(j["final_dist_m"].get<double>(), 0.11);
  EXPECT_FALSE(j.contains("contact_sheet"));  // only for rendered episodes
  e.sheet_path = "out/ep7.png";
  EXPECT_EQ(WalkEpisodeJson(e)["contact_sheet"], "out/ep7.png");

  WalkEvalSummary s;
  s.episodes = 100;
  s.success_rate = 0.99;
  s.fall_rate = 0.01;
  WalkEvalOptions o;
  o.policy = "assets/policies/walk.pt";
  o.seed = 2;
  nlohmann::ordered_json sj = WalkSummaryJson(s, o);
  EXPECT_EQ(sj["suite"], "walk");
  EXPECT_EQ(sj["episodes"], 100);
  EXPECT_DOUBLE_EQ(sj["success_rate"].get<double>(), 0.99);
  EXPECT_EQ(sj["policy"], "assets/policies/walk.pt");
  EXPECT_EQ(sj["seed"], 2);
  EXPECT_TRUE(sj.contains("git_revision"));  // provenance
}

TEST(WalkEval, StepSuiteAsksForShortStepsBehindOrBesideIntegration) {
  WalkEvalOptions o;
  o.policy = std::string(SIMHUMAN_SOURCE_DIR) + "/assets/policies/walk.pt";
  o.episodes = 3;
  o.seed = 5;
  o.time_limit_s = 6;
  o.step_suite = true;
  std::vector<WalkEpisode> eps;
  auto sum = RunWalkEval(o, &eps);
  ASSERT_TRUE(sum.ok()) << sum.status();
  ASSERT_EQ(eps.size(), 3u);
  for (const WalkEpisode& e : eps) {
    EXPECT_GE(e.dist_m, 0.5);
    EXPECT_LE(e.dist_m, 1.5);
    EXPECT_GE(std::abs(e.bearing_deg), 60.0) << e.index;
    EXPECT_LE(std::abs(e.bearing_deg), 180.0) << e.index;
    EXPECT_GE(e.max_turn_deg, 0.0);
    EXPECT_LE(e.max_turn_deg, 180.0);
    EXPECT_GT(e.arm_raise_deg, 0.0);
    EXPECT_LT(e.arm_raise_deg, 180.0);
  }
  EXPECT_EQ(WalkSummaryJson(*sum, o)["suite"], "walk-step");
  EXPECT_TRUE(WalkSummaryJson(*sum, o).contains("arm_raise_deg"));
  o.physics_solver = "cg";
  auto bad = RunWalkEval(o, nullptr);
  ASSERT_FALSE(bad.ok());
  EXPECT_NE(bad.status().message().find("cg"), std::string::npos) << bad.status();
}

}  // namespace
}  // namespace simhuman::eval

namespace simhuman::eval {
namespace {

// the shipped walking policy walks: UniHSI's far suites depend on it (label slow)
TEST(WalkEval, ShippedPolicyWalksToItsGoalsSlow) {
  WalkEvalOptions o;
  o.policy = std::string(SIMHUMAN_SOURCE_DIR) + "/assets/policies/walk.pt";
  o.episodes = 10;
  o.seed = 1;
  std::vector<WalkEpisode> eps;
  auto sum = RunWalkEval(o, &eps);
  ASSERT_TRUE(sum.ok()) << sum.status();
  EXPECT_GE(sum->success_rate, 0.9);
  EXPECT_EQ(sum->fall_rate, 0.0);
  EXPECT_GT(sum->mean_time_s, 0.0);
  // steady walking was seen and measured against the norms
  EXPECT_GT(sum->motion.walking_s, 10.0);
  EXPECT_GT(sum->motion.speed_mps, 0.5);
  EXPECT_GT(sum->motion.cadence_spm, 60.0);
}

TEST(WalkEval, TheShippedPolicyWalksAChildAndATallAdultSlow) {
  // the same adult-trained policy in the adult's units (control::WalkScale); before Froude
  // scaling both fell in every episode
  for (double scale : {0.6, 1.2}) {
    WalkEvalOptions o;
    o.policy = std::string(SIMHUMAN_SOURCE_DIR) + "/assets/policies/walk.pt";
    o.episodes = 8;
    o.seed = 1;
    o.scale = scale;
    std::vector<WalkEpisode> eps;
    auto sum = RunWalkEval(o, &eps);
    ASSERT_TRUE(sum.ok()) << sum.status();
    EXPECT_GE(sum->success_rate, 0.85) << "scale " << scale;
    EXPECT_NEAR(sum->motion.scale, scale, 1e-12);
  }
}

}  // namespace
}  // namespace simhuman::eval
