#pragma once
/// MuJoCo 2.2.2 health: its default error handler prints, waits for Enter and exits, and it
/// silently resets the state on divergence. We install our own handlers and read the warning
/// counters every step so an episode ends with a reason instead.

#include <mujoco/mujoco.h>

#include <array>
#include <string>

namespace simhuman::world {

/// Installs process-wide MuJoCo error and warning handlers (idempotent, thread-safe).
/// Errors print "simhuman: MuJoCo error: <msg>" to stderr and exit the process with code 3;
/// warnings are counted and the first few printed.
///
/// Why the error handler exits, although library code otherwise never does: MuJoCo 2.2.2 calls
/// it from deep inside C code (allocation failures, a model it cannot step) and has no way to
/// unwind; if the handler returns, MuJoCo carries on with a half-updated mjData. Throwing a C++
/// exception through MuJoCo's C frames (built without unwind tables) is undefined, and longjmp
/// would skip our destructors. So the only safe response is to end the process at once, with
/// exit code 3, which `simhuman` documents ("MuJoCo error"). Everything that can be checked
/// before MuJoCo sees it (model XML, sizes, finite numbers) is checked by our parsers and
/// returned as a status instead, so this handler is the last resort, not the error path.
void InstallMujocoHandlers();

/// Number of MuJoCo warnings seen by the handler since start-up.
long MujocoWarningCount();

/// What went wrong in the last step, if anything.
enum class HealthStatus { kOk, kUnstable, kNonFinite };

/// Per-step health report. `status != kOk` ends an episode with `reason`.
struct HealthReport {
  HealthStatus status = HealthStatus::kOk;
  std::string reason;  ///< e.g. "unstable: bad qacc (MuJoCo reset the state) at t=3.21 s"
  bool ok() const { return status == HealthStatus::kOk; }
};

/// Remembers warning counters between steps.
class HealthMonitor {
 public:
  /// Call after every mj_step (or mj_forward). Detects MuJoCo's divergence resets (bad qpos,
  /// qvel, qacc warnings), non-finite state, and runaway velocities (> `max_qvel`).
  HealthReport Check(const mjModel* m, const mjData* d);
  /// Forget counters (after a deliberate reset).
  void Reset(const mjData* d);
  double max_qvel = 200.0;

 private:
  std::array<int, mjNWARNING> last_{};
};

/// True if every entry of `x` is finite.
bool AllFinite(const mjtNum* x, int n);

}  // namespace simhuman::world
