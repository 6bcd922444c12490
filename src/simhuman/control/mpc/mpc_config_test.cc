#include "simhuman/control/mpc/mpc_config.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <string>

namespace simhuman::control {
namespace {

using nlohmann::json;
using ::testing::HasSubstr;

std::string Error(const json& j) {
  absl::StatusOr<MpcConfig> c = MpcConfig::FromJson(j, "cfg.json");
  return c.ok() ? std::string() : std::string(c.status().message());
}

TEST(MpcConfigTable, PresetsGiveTheMissingKeysAndToJsonWritesEveryKey) {
  auto quality = MpcConfig::FromJson(json{{"preset", "quality"}, {"knots", 5}}, "cfg.json");
  ASSERT_TRUE(quality.ok()) << quality.status();
  EXPECT_EQ(quality->samples, 32);
  EXPECT_EQ(quality->replan_s, 0.02);
  EXPECT_EQ(quality->knots, 5);
  auto fast = MpcConfig::FromJson(json::object(), "");
  ASSERT_TRUE(fast.ok()) << fast.status();
  EXPECT_EQ(fast->ToJson(), MpcConfig().ToJson());
  json j = quality->ToJson();
  EXPECT_EQ(j.size(), 26u);  // "preset" and the 25 settings
  EXPECT_EQ(j["preset"], "quality");
  EXPECT_TRUE(j["samples"].is_number_integer());
  auto back = MpcConfig::FromJson(json::parse(j.dump()), "cfg.json");
  ASSERT_TRUE(back.ok()) << back.status();
  EXPECT_EQ(back->ToJson(), j);
  EXPECT_TRUE(MpcConfig::FromJson(json{{"samples", 16.0}}, "cfg.json").ok());
}

TEST(MpcConfigTable, ErrorsNameTheFileTheKeyTheValueAndTheRange) {
  EXPECT_EQ(Error(json{{"samples", 0}}),
            "cfg.json: mpc config 'samples' = 0 is invalid; valid range is [2, 1024]");
  EXPECT_EQ(Error(json{{"noise_rad", 1.5}}),
            "cfg.json: mpc config 'noise_rad' = 1.5 is invalid; valid range is [0, 1]");
  EXPECT_THAT(Error(json{{"sampels", 8}}),
              HasSubstr("cfg.json: /: unknown key 'sampels'; valid keys are: preset, samples"));
  EXPECT_EQ(Error(json{{"samples", 8.5}}), "cfg.json: /samples: expected an integer, got 8.5");
  EXPECT_EQ(Error(json{{"samples", 1e300}}),
            "cfg.json: /samples: expected an integer in [-2147483648, 2147483647], got 1e+300");
  EXPECT_EQ(Error(json{{"w_track", "4"}}), "cfg.json: /w_track: expected a number, got string");
  EXPECT_EQ(Error(json{{"preset", "turbo"}}),
            "cfg.json: /preset: unknown preset 'turbo'; valid presets are: fast, quality");
  EXPECT_THAT(Error(json{{"min_ramp_s", 2}, {"max_ramp_s", 1}}),
              HasSubstr("min_ramp_s must not exceed max_ramp_s"));
  EXPECT_EQ(Error(json::array()), "cfg.json: /: expected a JSON object, got array");
}

}  // namespace
}  // namespace simhuman::control
