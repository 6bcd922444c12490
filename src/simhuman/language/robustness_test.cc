// Hostile inputs to the offline planner: random bytes, invalid UTF-8, a 1 MB command, 10,000
// clauses. Every call must return a status (no crash) in bounded time.

#include <gtest/gtest.h>

#include <chrono>
#include <random>
#include <string>

#include "simhuman/language/offline_planner.h"
#include "simhuman/world/scene.h"

namespace simhuman::language {
namespace {

// generous bound for one call on a loaded 2-core machine
constexpr double kMaxCallMs = 200.0;
constexpr int kRandomCommands = 2000;
constexpr uint32_t kSeed = 12345;

class RobustnessTest : public ::testing::Test {
 protected:
  void SetUp() override {
    catalog_ = *world::BuildCatalog(*world::BuiltinScene("living_room"));
    context_.scene = &catalog_;
    context_.agents.push_back({4.0, -1.35, M_PI / 2, "stand"});
  }
  // plans `command` and checks the time; returns the status
  absl::Status Plan(const std::string& command) {
    const auto t0 = std::chrono::steady_clock::now();
    core::StatusOr<PlanResult> r = planner_.Plan(command, context_);
    const double ms =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
    EXPECT_LT(ms, kMaxCallMs) << command.substr(0, 80);
    if (r.ok()) {
      EXPECT_EQ(r->explanation.size(), r->chain.steps.size());
    }
    return r.status();
  }

  core::SceneCatalog catalog_;
  PlanContext context_;
  OfflinePlanner planner_;
};

TEST_F(RobustnessTest, RandomBytesReturnAStatus) {
  std::mt19937 rng(kSeed);
  for (int i = 0; i < kRandomCommands; ++i) {
    std::string s(rng() % 200, '\0');
    for (char& c : s) c = static_cast<char>(rng() & 0xff);
    absl::Status st = Plan(s);
    if (!st.ok()) {
      EXPECT_TRUE(absl::IsInvalidArgument(st) || absl::IsFailedPrecondition(st)) << st;
    }
  }
}

TEST_F(RobustnessTest, RandomVocabularyReturnsAStatus) {
  const char* words[] = {"sit",   "on",       "the",  "chair", "then",  "lie",  "bed",
                         "it",    "and",      "put",  "red",   "box",   "left", "of",
                         "hands", "knees",    ",",    "up",    "stand", "go",   "to",
                         "sofa",  "armrests", "with", "your",  "touch"};
  std::mt19937 rng(kSeed);
  for (int i = 0; i < kRandomCommands; ++i) {
    std::string s;
    const int n = 1 + static_cast<int>(rng() % 12);
    for (int k = 0; k < n; ++k) s += std::string(words[rng() % std::size(words)]) + " ";
    absl::Status st = Plan(s);
    if (!st.ok()) {
      EXPECT_TRUE(absl::IsInvalidArgument(st) || absl::IsFailedPrecondition(st)) << s << st;
    }
  }
}

TEST_F(RobustnessTest, InvalidUtf8IsRefusedWithTheOffset) {
  absl::Status st = Plan("sit on the \xc3\x28 chair");
  EXPECT_TRUE(absl::IsInvalidArgument(st)) << st;
  EXPECT_NE(std::string(st.message()).find("offset 11"), std::string::npos) << st;
  EXPECT_TRUE(absl::IsInvalidArgument(Plan("\xff\xfe\xfd")));
  EXPECT_TRUE(absl::IsInvalidArgument(Plan(std::string("sit\0on", 6))));
}

TEST_F(RobustnessTest, OneMegabyteIsRefusedQuickly) {
  std::string big(1 << 20, 'a');
  absl::Status st = Plan(big);
  EXPECT_TRUE(absl::IsInvalidArgument(st)) << st;
  EXPECT_NE(std::string(st.message()).find("at most"), std::string::npos);
}

TEST_F(RobustnessTest, TenThousandClausesAreRefused) {
  std::string s;
  for (int i = 0; i < 10000; ++i) s += "sit,";
  absl::Status st = Plan(s);
  EXPECT_TRUE(absl::IsInvalidArgument(st)) << st;
  // within the byte limit, the clause limit speaks
  std::string many;
  for (int i = 0; i < 100; ++i) many += "lie, ";
  st = Plan(many);
  EXPECT_TRUE(absl::IsInvalidArgument(st)) << st;
  EXPECT_NE(std::string(st.message()).find("clauses"), std::string::npos) << st;
}

TEST_F(RobustnessTest, NoSceneIsAnError) {
  PlanContext empty;
  EXPECT_TRUE(absl::IsInvalidArgument(planner_.Plan("sit", empty).status()));
}

}  // namespace
}  // namespace simhuman::language
