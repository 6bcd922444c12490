#include "simhuman/eval/language_suite.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>

#include "simhuman/language/offline_planner.h"

namespace simhuman::eval {
namespace {

// targets of issue 3 for the offline planner on the hand-written corpus
constexpr double kMinExactRate = 0.97;
constexpr double kMinRefusedRate = 1.0;
constexpr int kMinCorpusCommands = 300;
constexpr double kMaxMedianLatencyUs = 1000.0;

TEST(LanguageSuiteTest, OfflinePlannerMeetsTheCorpusTargets) {
  const std::string path = DefaultLanguageCorpusPath();
  core::StatusOr<std::vector<LanguageCase>> cases = LoadLanguageCorpus(path);
  ASSERT_TRUE(cases.ok()) << cases.status();
  EXPECT_GE(static_cast<int>(cases->size()), kMinCorpusCommands);
  language::OfflinePlanner planner;
  core::StatusOr<LanguageSummary> s =
      RunLanguageCorpus(*cases, std::filesystem::path(path).parent_path().string(), planner);
  ASSERT_TRUE(s.ok()) << s.status();
  for (const LanguageCaseResult& r : s->results) {
    if (!r.pass) {
      ADD_FAILURE() << "line " << r.c.line << " [" << r.c.scene << "] \"" << r.c.command << "\" -> "
                    << r.got;
    }
  }
  EXPECT_GE(s->exact_rate(), kMinExactRate);
  EXPECT_GE(s->refused_rate(), kMinRefusedRate);
  EXPECT_LT(s->median_latency_us, kMaxMedianLatencyUs);
  std::printf(
      "language corpus: %d cases, exact %d/%d, refused %d/%d, errors %d/%d, median %.1f us, "
      "p99 %.1f us\n",
      s->cases, s->plan_exact, s->plan_cases, s->ambiguous_refused, s->ambiguous_cases,
      s->error_correct, s->error_cases, s->median_latency_us, s->p99_latency_us);
}

TEST(LanguageSuiteTest, MalformedCorpusLinesNameTheLine) {
  const std::string path = (std::filesystem::temp_directory_path() /
                            ("simhuman_malformed_corpus_" + std::to_string(getpid()) + ".jsonl"))
                               .string();
  {
    std::FILE* f = std::fopen(path.c_str(), "w");
    ASSERT_NE(f, nullptr);
    std::fputs("{\"scene\": \"sit_demo\", \"command\": \"sit\", \"expect_error\": true}\n", f);
    std::fputs("{\"scene\": \"sit_demo\", \"command\": \"sit\", \"expect\": []}\n", f);
    std::fclose(f);
  }
  core::StatusOr<std::vector<LanguageCase>> cases = LoadLanguageCorpus(path);
  ASSERT_FALSE(cases.ok());
  EXPECT_NE(std::string(cases.status().message()).find(":2:"), std::string::npos) << cases.status();
  std::filesystem::remove(path);
}

}  // namespace
}  // namespace simhuman::eval
