#include "simhuman/app/llm_flags.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace simhuman::app {
namespace {

using ::testing::HasSubstr;
using ::testing::StartsWith;

class NullPlanner : public language::Planner {
 public:
  core::StatusOr<language::PlanResult> Plan(std::string_view,
                                            const language::PlanContext&) override {
    return absl::UnimplementedError("null");
  }
  std::string name() const override { return "null"; }
};

// parses `args` (after the program name) into flags
LlmFlags Parse(std::vector<std::string> args) {
  CLI::App app{"test"};
  LlmFlags flags;
  AddLlmFlags(app, flags);
  args.insert(args.begin(), "prog");
  std::vector<const char*> argv;
  for (const std::string& a : args) argv.push_back(a.c_str());
  app.parse(static_cast<int>(argv.size()), argv.data());
  return flags;
}

std::string Error(const std::vector<std::string>& args, language::Planner* fallback = nullptr) {
  core::StatusOr<language::LlmPlannerOptions> o = LlmOptionsFromFlags(Parse(args), fallback);
  return o.ok() ? "" : std::string(o.status().message());
}

TEST(LlmFlagsTest, FlagsBecomeOptions) {
  NullPlanner offline;
  core::StatusOr<language::LlmPlannerOptions> o = LlmOptionsFromFlags(
      Parse({"--llm-url", "http://localhost:11434/v1", "--llm-model", "qwen2.5:7b", "--llm-timeout",
             "12.5", "--llm-key-env", "OLLAMA_KEY", "--llm-fallback"}),
      &offline);
  ASSERT_TRUE(o.ok()) << o.status();
  EXPECT_EQ(o->chat.url, "http://localhost:11434/v1");
  EXPECT_EQ(o->chat.model, "qwen2.5:7b");
  EXPECT_EQ(o->chat.timeout_s, 12.5);
  EXPECT_EQ(o->api_key_env, "OLLAMA_KEY");
  EXPECT_EQ(o->fallback, &offline);
  EXPECT_EQ(o->max_repair_rounds, 2);
}

TEST(LlmFlagsTest, DefaultsNeedOnlyAModel) {
  core::StatusOr<language::LlmPlannerOptions> o =
      LlmOptionsFromFlags(Parse({"--llm-model", "m"}), nullptr);
  ASSERT_TRUE(o.ok()) << o.status();
  EXPECT_EQ(o->chat.url, "http://127.0.0.1:8080/v1");
  EXPECT_EQ(o->api_key_env, "SIMHUMAN_LLM_API_KEY");
  EXPECT_EQ(o->fallback, nullptr);
}

TEST(LlmFlagsTest, ErrorsNameTheFlag) {
  EXPECT_THAT(Error({}), StartsWith("--llm-model: a model name is required"));
  EXPECT_THAT(Error({"--llm-model", "m", "--llm-url", "localhost:8080"}),
              StartsWith("--llm-url: invalid URL 'localhost:8080'"));
  EXPECT_THAT(Error({"--llm-model", "m", "--llm-timeout", "-1"}),
              StartsWith("--llm-timeout: must be in (0, 3600] seconds, got -1"));
  EXPECT_THAT(Error({"--llm-model", "m", "--llm-key-env", "MY-KEY"}),
              StartsWith("--llm-key-env: 'MY-KEY' is not an environment variable name"));
  EXPECT_THAT(Error({"--llm-model", "m", "--llm-fallback"}),
              HasSubstr("--llm-fallback: no fallback planner"));
}

}  // namespace
}  // namespace simhuman::app
