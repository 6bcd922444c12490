#include "simhuman/learn/team_carry_env.h"

#include <algorithm>
#include <cmath>

#include "simhuman/core/check.h"
#include "simhuman/core/rng.h"

namespace simhuman::learn {

TeamCarryTask::TeamCarryTask(int num_envs, int num_agents)
    : agents_(num_agents), envs_(std::max(1, num_envs)) {
  SH_CHECK(num_agents >= 2 && num_agents <= 8, "TeamCarryTask needs 2 to 8 agents");
  for (Env& e : envs_) e.agents.resize(agents_);
}

void TeamCarryTask::Observe(const Env& e, float* obs, float* state) const {
  const int d = obs_dim();
  for (int a = 0; a < agents_; ++a) {
    const Agent& me = e.agents[a];
    float* o = obs + a * d;
    for (int k = 0; k < 2; ++k) {
      o[k] = static_cast<float>(me.p[k]);
      o[2 + k] = static_cast<float>(me.v[k]);
      o[4 + k] = static_cast<float>(e.box[k] - me.p[k]);
      o[6 + k] = static_cast<float>(e.goal[k] - e.box[k]);
    }
    int slot = 8;
    for (int b = 0; b < agents_; ++b) {
      if (b == a) continue;
      for (int k = 0; k < 2; ++k) o[slot + k] = static_cast<float>(e.agents[b].p[k] - me.p[k]);
      slot += 2;
    }
  }
  for (int a = 0; a < agents_; ++a) {
    for (int k = 0; k < 2; ++k) {
      state[4 * a + k] = static_cast<float>(e.agents[a].p[k]);
      state[4 * a + 2 + k] = static_cast<float>(e.agents[a].v[k]);
    }
  }
  for (int k = 0; k < 2; ++k) {
    state[4 * agents_ + k] = static_cast<float>(e.box[k]);
    state[4 * agents_ + 2 + k] = static_cast<float>(e.goal[k]);
  }
}

void TeamCarryTask::Reset(int i, uint64_t seed, float* obs, float* state) {
  core::Rng rng(seed);
  Env& e = envs_[i];
  for (int k = 0; k < 2; ++k) {
    e.box[k] = rng.Uniform(-0.8, 0.8);
    e.goal[k] = rng.Uniform(-1, 1);
  }
  for (Agent& a : e.agents) {
    for (int k = 0; k < 2; ++k) {
      a.p[k] = rng.Uniform(-1, 1);
      a.v[k] = 0;
    }
  }
  e.steps = 0;
  Observe(e, obs, state);
}

void TeamCarryTask::Step(int i, const float* actions, float* obs, float* state, float* rewards,
                         TeamStepInfo* info) {
  constexpr double kDt = 0.05, kDrag = 1.0, kGain = 4.0, kBound = 2.0;
  Env& e = envs_[i];
  // the box follows the agents' mean velocity while all of them hold it (before they move)
  bool held = true;
  for (const Agent& a : e.agents) {
    held = held && std::hypot(a.p[0] - e.box[0], a.p[1] - e.box[1]) < kGripM;
  }
  double box_v[2] = {0, 0};
  for (int a = 0; a < agents_; ++a) {
    Agent& ag = e.agents[a];
    for (int k = 0; k < 2; ++k) {
      double f = std::clamp(static_cast<double>(actions[a * 2 + k]), -1.0, 1.0);
      ag.v[k] += kDt * (kGain * f - kDrag * ag.v[k]);
      ag.p[k] = std::clamp(ag.p[k] + kDt * ag.v[k], -kBound, kBound);
      box_v[k] += ag.v[k] / agents_;
    }
  }
  if (held) {
    for (int k = 0; k < 2; ++k) e.box[k] = std::clamp(e.box[k] + kDt * box_v[k], -kBound, kBound);
  }
  ++e.steps;
  Observe(e, obs, state);
  const double to_goal = std::hypot(e.goal[0] - e.box[0], e.goal[1] - e.box[1]);
  const double team = std::exp(-to_goal / kRewardScaleM);
  for (int a = 0; a < agents_; ++a) {
    const Agent& ag = e.agents[a];
    double to_box = std::hypot(e.box[0] - ag.p[0], e.box[1] - ag.p[1]);
    rewards[a] = static_cast<float>(kApproachWeight * std::exp(-to_box / kRewardScaleM) + team);
  }
  info->terminated = false;
  info->truncated = e.steps >= kMaxSteps;
  info->success = to_goal < kSuccessM;
}

}  // namespace simhuman::learn
