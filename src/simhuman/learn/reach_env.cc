#include "simhuman/learn/reach_env.h"

#include <algorithm>
#include <cmath>

namespace simhuman::learn {

ReachTask::ReachTask(int num_envs) : envs_(std::max(1, num_envs)) {}

void ReachTask::Observe(const Env& e, float* obs) const {
  for (int k = 0; k < 2; ++k) {
    obs[k] = static_cast<float>(e.p[k]);
    obs[2 + k] = static_cast<float>(e.v[k]);
    obs[4 + k] = static_cast<float>(e.t[k] - e.p[k]);
  }
}

void ReachTask::Reset(int i, uint64_t seed, float* obs) {
  core::Rng rng(seed);
  Env& e = envs_[i];
  for (int k = 0; k < 2; ++k) {
    e.p[k] = rng.Uniform(-1, 1);
    e.v[k] = 0;
    e.t[k] = rng.Uniform(-1, 1);
  }
  e.steps = 0;
  Observe(e, obs);
}

void ReachTask::Step(int i, const float* action, float* obs, StepInfo* info) {
  constexpr double kDt = 0.05, kDrag = 1.0, kGain = 4.0;
  Env& e = envs_[i];
  for (int k = 0; k < 2; ++k) {
    double f = std::clamp(static_cast<double>(action[k]), -1.0, 1.0);
    e.v[k] += kDt * (kGain * f - kDrag * e.v[k]);
    e.p[k] = std::clamp(e.p[k] + kDt * e.v[k], -2.0, 2.0);
  }
  double dist = std::hypot(e.t[0] - e.p[0], e.t[1] - e.p[1]);
  ++e.steps;
  Observe(e, obs);
  info->reward = static_cast<float>(1.0 - std::min(dist, 1.0));
  info->terminated = false;
  info->truncated = e.steps >= kMaxSteps;
  info->success = dist < 0.1;
}

}  // namespace simhuman::learn
