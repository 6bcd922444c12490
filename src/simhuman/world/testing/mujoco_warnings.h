#pragma once
/// Test support: every test binary that links world/ fails a test during which MuJoCo warned,
/// unless the test says it expects warnings (a test that provokes divergence on purpose).
/// The listener is installed by mujoco_warnings.cc, which CMake adds to those test binaries.

namespace simhuman::world::testing {

/// While alive, MuJoCo warnings do not fail the running test.
class ScopedExpectMujocoWarnings {
 public:
  ScopedExpectMujocoWarnings();
  ~ScopedExpectMujocoWarnings();
  ScopedExpectMujocoWarnings(const ScopedExpectMujocoWarnings&) = delete;
  ScopedExpectMujocoWarnings& operator=(const ScopedExpectMujocoWarnings&) = delete;
};

}  // namespace simhuman::world::testing
