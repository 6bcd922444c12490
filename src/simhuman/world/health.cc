#include "simhuman/world/health.h"

#include <atomic>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <mutex>

namespace simhuman::world {
namespace {

std::atomic<long> g_warnings{0};

void OnError(const char* msg) {
  std::fprintf(stderr, "simhuman: MuJoCo error: %s\n", msg);
  std::fflush(stderr);
  std::_Exit(3);
}

void OnWarning(const char* msg) {
  long n = ++g_warnings;
  if (n <= 5) std::fprintf(stderr, "simhuman: MuJoCo warning: %s\n", msg);
}

}  // namespace

void InstallMujocoHandlers() {
  static std::once_flag once;
  std::call_once(once, [] {
    mju_user_error = OnError;
    mju_user_warning = OnWarning;
  });
}

long MujocoWarningCount() { return g_warnings.load(); }

bool AllFinite(const mjtNum* x, int n) {
  for (int i = 0; i < n; ++i) {
    if (!std::isfinite(x[i])) return false;
  }
  return true;
}

void HealthMonitor::Reset(const mjData* d) {
  for (int i = 0; i < mjNWARNING; ++i) last_[i] = d->warning[i].number;
}

HealthReport HealthMonitor::Check(const mjModel* m, const mjData* d) {
  HealthReport r;
  auto fail = [&](HealthStatus s, const std::string& why) {
    r.status = s;
    char buf[64];
    std::snprintf(buf, sizeof(buf), " at t=%.3f s", d->time);
    r.reason = why + buf;
  };
  static const struct {
    int id;
    const char* what;
  } kResets[] = {{mjWARN_BADQPOS, "bad qpos"},
                 {mjWARN_BADQVEL, "bad qvel"},
                 {mjWARN_BADQACC, "bad qacc"},
                 {mjWARN_BADCTRL, "bad ctrl"}};
  for (const auto& w : kResets) {
    if (d->warning[w.id].number > last_[w.id]) {
      fail(HealthStatus::kUnstable,
           std::string("unstable: ") + w.what + " (MuJoCo reset or zeroed the state)");
    }
  }
  for (int i = 0; i < mjNWARNING; ++i) last_[i] = d->warning[i].number;
  if (!r.ok()) return r;
  if (!AllFinite(d->qpos, m->nq) || !AllFinite(d->qvel, m->nv) || !AllFinite(d->ctrl, m->nu)) {
    fail(HealthStatus::kNonFinite, "unstable: non-finite state or control");
    return r;
  }
  for (int i = 0; i < m->nv; ++i) {
    if (std::abs(d->qvel[i]) > max_qvel) {
      fail(HealthStatus::kUnstable, "unstable: runaway velocity in dof " + std::to_string(i));
      return r;
    }
  }
  return r;
}

}  // namespace simhuman::world
