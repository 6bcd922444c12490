#include "simhuman/learn/multi_agent_env.h"

#include <cstring>

#include "simhuman/core/rng.h"

namespace simhuman::learn {

MultiAgentVecEnv::MultiAgentVecEnv(std::unique_ptr<MultiAgentVecTask> task, int threads,
                                   uint64_t seed)
    : task_(std::move(task)), pool_(threads), seed_(seed) {
  const size_t e = static_cast<size_t>(task_->num_envs());
  const size_t rows = e * static_cast<size_t>(task_->num_agents());
  obs_.assign(rows * task_->obs_dim(), 0.f);
  terminal_obs_ = obs_;
  state_.assign(e * task_->state_dim(), 0.f);
  terminal_state_ = state_;
  rewards_.assign(rows, 0.f);
  terminated_.assign(e, 0);
  truncated_.assign(e, 0);
  ended_.assign(e, 0);
  ep_ret_.assign(rows, 0.0);
  ep_len_.assign(e, 0);
  ep_count_.assign(e, 0);
  ep_done_.assign(e, TeamEpisodeStats());
}

void MultiAgentVecEnv::ResetOne(int i) {
  const size_t n = static_cast<size_t>(num_agents());
  task_->Reset(i, core::DeriveSeed(seed_, static_cast<uint64_t>(i), ep_count_[i]++),
               obs_.data() + i * n * obs_dim(),
               state_.data() + static_cast<size_t>(i) * state_dim());
  for (size_t a = 0; a < n; ++a) ep_ret_[i * n + a] = 0;
  ep_len_[i] = 0;
}

void MultiAgentVecEnv::ResetAll(uint64_t episode_base) {
  pool_.ParallelFor(num_envs(), [&](int i) {
    ep_count_[i] = episode_base;
    ResetOne(i);
  });
}

void MultiAgentVecEnv::StepOne(int i, const float* actions) {
  const size_t n = static_cast<size_t>(num_agents());
  const size_t od = n * obs_dim(), sd = static_cast<size_t>(state_dim());
  float* o = obs_.data() + i * od;
  float* s = state_.data() + i * sd;
  float* r = rewards_.data() + i * n;
  TeamStepInfo info;
  task_->Step(i, actions, o, s, r, &info);
  terminated_[i] = info.terminated;
  truncated_[i] = info.truncated && !info.terminated;
  ++ep_len_[i];
  for (size_t a = 0; a < n; ++a) ep_ret_[i * n + a] += r[a];
  ended_[i] = info.terminated || info.truncated;
  if (!ended_[i]) return;
  std::memcpy(terminal_obs_.data() + i * od, o, sizeof(float) * od);
  std::memcpy(terminal_state_.data() + i * sd, s, sizeof(float) * sd);
  TeamEpisodeStats& done = ep_done_[i];
  done.agent_returns.assign(ep_ret_.begin() + i * n, ep_ret_.begin() + (i + 1) * n);
  double sum = 0;
  for (double x : done.agent_returns) sum += x;
  done.team = EpisodeStats{sum / static_cast<double>(n), ep_len_[i], info.success, info.terminated};
  ResetOne(i);
}

void MultiAgentVecEnv::Step(const float* actions) {
  const size_t per_env = static_cast<size_t>(num_agents()) * act_dim();
  pool_.ParallelFor(num_envs(), [&](int i) { StepOne(i, actions + i * per_env); });
  finished_.clear();
  for (int i = 0; i < num_envs(); ++i) {
    if (ended_[i]) finished_.push_back(ep_done_[i]);
  }
}

}  // namespace simhuman::learn
