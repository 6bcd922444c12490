#include "simhuman/world/testing/mujoco_warnings.h"

#include <gtest/gtest.h>

#include <atomic>

#include "simhuman/world/health.h"

namespace simhuman::world::testing {
namespace {

std::atomic<long> g_allowed{0};  // warnings seen while a ScopedExpectMujocoWarnings was alive
std::atomic<int> g_scopes{0};
long g_scope_start = 0;

// counts MuJoCo's warnings over each test and fails the test when any were unexpected
class MujocoWarningListener : public ::testing::EmptyTestEventListener {
 public:
  void OnTestStart(const ::testing::TestInfo&) override {
    InstallMujocoHandlers();
    start_ = MujocoWarningCount();
    g_allowed = 0;
  }
  void OnTestEnd(const ::testing::TestInfo& info) override {
    const long unexpected = MujocoWarningCount() - start_ - g_allowed.load();
    if (unexpected > 0) {
      ADD_FAILURE_AT(info.file(), info.line())
          << "MuJoCo warned " << unexpected
          << " time(s) during this test (the handler printed the first ones); a test that "
             "provokes warnings on purpose holds a ScopedExpectMujocoWarnings";
    }
  }

 private:
  long start_ = 0;
};

// registered before main() runs the tests
const bool kRegistered = [] {
  ::testing::UnitTest::GetInstance()->listeners().Append(new MujocoWarningListener);
  return true;
}();

}  // namespace

ScopedExpectMujocoWarnings::ScopedExpectMujocoWarnings() {
  if (g_scopes++ == 0) g_scope_start = MujocoWarningCount();
}

ScopedExpectMujocoWarnings::~ScopedExpectMujocoWarnings() {
  if (--g_scopes == 0) g_allowed += MujocoWarningCount() - g_scope_start;
}

}  // namespace simhuman::world::testing
