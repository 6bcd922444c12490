#include "simhuman/learn/ppo_rollout.h"

#include <omp.h>

#include <vector>

#include "simhuman/learn/gae.h"
#include "simhuman/learn/ppo_amp.h"

namespace simhuman::learn {

RolloutBuffer RolloutBuffer::Make(int steps, int rows, int obs_dim, int act_dim, int critic_dim) {
  RolloutBuffer b;
  b.obs = torch::empty({steps, rows, obs_dim});
  if (critic_dim > 0) b.critic_obs = torch::empty({steps, rows, critic_dim});
  b.act = torch::empty({steps, rows, act_dim});
  b.logp = torch::empty({steps, rows});
  b.value = torch::empty({steps, rows});
  b.reward = torch::empty({steps, rows});
  b.done = torch::empty({steps, rows});
  return b;
}

PpoBatch RolloutBuffer::Finish(float gamma, float lambda) const {
  torch::Tensor adv = ComputeGae(reward, value, done, last_value, gamma, lambda);
  torch::Tensor ret = adv + value;
  const int64_t n = obs.size(0) * obs.size(1);
  PpoBatch b;
  b.obs = obs.reshape({n, obs.size(2)});
  if (critic_obs.defined()) b.critic_obs = critic_obs.reshape({n, critic_obs.size(2)});
  b.act = act.reshape({n, act.size(2)});
  b.old_logp = logp.reshape({n});
  b.old_value = value.reshape({n});
  b.ret = ret.reshape({n});
  b.adv = adv.reshape({n});
  return b;
}

void EpisodeWindow::Add(const EpisodeStats& e) {
  episodes_.push_back(e);
  if (episodes_.size() > capacity_) episodes_.pop_front();
}

EpisodeMeans EpisodeWindow::Means() const {
  EpisodeMeans m;
  if (episodes_.empty()) return m;
  for (const auto& e : episodes_) {
    m.ret += e.ret;
    m.length += e.length;
    m.success += e.success;
    m.fall += e.terminated;
  }
  double n = static_cast<double>(episodes_.size());
  m.ret /= n;
  m.length /= n;
  m.success /= n;
  m.fall /= n;
  return m;
}

RolloutBuffer CollectVecRollout(VecEnv& env, ActorCritic& net, control::ObsNormalizer& norm,
                                core::Rng& rng, AmpStage* amp, const VecRolloutOptions& options,
                                const std::function<void(const EpisodeStats&)>& on_episode) {
  const int E = env.num_envs(), D = env.obs_dim(), A = env.act_dim(), T = options.steps;
  RolloutBuffer buf = RolloutBuffer::Make(T, E, D, A);
  if (amp) amp->BeginRollout(T, E);
  torch::NoGradGuard ng;
  net.actor->eval();
  torch::Tensor log_std = net.actor->log_std();
  torch::Tensor std_dev = torch::exp(log_std);
  for (int t = 0; t < T; ++t) {
    torch::Tensor raw = torch::from_blob(const_cast<float*>(env.obs().data()), {E, D});
    norm.Update(raw);
    // the exploration noise is drawn here, in env order, so results do not depend on chunks
    torch::Tensor noise = DrawGaussian(rng, E, A);
    torch::Tensor t_obs = buf.obs[t], t_act = buf.act[t], t_logp = buf.logp[t];
    torch::Tensor t_val = buf.value[t];
    // policy and value of envs [b, e): reads their raw observations, fills the buffers
    auto infer = [&](int b, int e, const float* obs_rows, float* act_rows) {
      torch::NoGradGuard ng_thread;  // grad mode is per thread
      torch::Tensor o = norm.Normalize(
          torch::from_blob(const_cast<float*>(obs_rows) + static_cast<int64_t>(b) * D, {e - b, D}));
      torch::Tensor mean = net.actor->forward(o);
      torch::Tensor act = mean + std_dev * noise.slice(0, b, e);
      t_obs.slice(0, b, e).copy_(o);
      t_act.slice(0, b, e).copy_(act);
      t_logp.slice(0, b, e).copy_(GaussianLogProb(act, mean, log_std, net.act_used));
      t_val.slice(0, b, e).copy_(net.critic->forward(o).squeeze(-1));
      torch::from_blob(act_rows + static_cast<int64_t>(b) * A, {e - b, A}).copy_(act);
    };
    if (options.chunks > 0) {
      env.StepChunked(
          [&](int b, int e, const float* obs_rows, float* act_rows) {
            // OpenMP thread counts are per thread (LibTorch's and OpenBLAS's): one per worker
            if (omp_get_max_threads() != 1) omp_set_num_threads(1);
            infer(b, e, obs_rows, act_rows);
          },
          options.chunks);
    } else {
      std::vector<float> actions(static_cast<size_t>(E) * A);
      infer(0, E, env.obs().data(), actions.data());
      env.Step(actions.data());
    }
    torch::Tensor rew = torch::from_blob(const_cast<float*>(env.rewards().data()), {E}).clone();
    // the style reward of the step's (s_t, s_t+1); the time-limit bootstrap below is added to
    // the mixed reward
    if (amp) rew = amp->MixReward(t, rew, env.amp_pairs().data());
    torch::Tensor done = torch::zeros({E});
    std::vector<int64_t> trunc;
    for (int i = 0; i < E; ++i) {
      if (env.terminated()[i] || env.truncated()[i]) done[i] = 1.f;
      if (env.truncated()[i]) trunc.push_back(i);
    }
    // time limits: bootstrap with the value of the last observation
    if (!trunc.empty()) {
      torch::Tensor term = torch::from_blob(const_cast<float*>(env.terminal_obs().data()), {E, D});
      torch::Tensor idx = torch::tensor(trunc, torch::kInt64);
      torch::Tensor v = net.critic->forward(norm.Normalize(term.index_select(0, idx))).squeeze(-1);
      AddTimeLimitBootstrap(rew, trunc, v, options.gamma);
    }
    buf.reward[t] = rew;
    buf.done[t] = done;
    for (const EpisodeStats& e : env.finished()) on_episode(e);
  }
  torch::Tensor last = torch::from_blob(const_cast<float*>(env.obs().data()), {E, D});
  buf.last_value = net.critic->forward(norm.Normalize(last)).squeeze(-1);
  return buf;
}

}  // namespace simhuman::learn
