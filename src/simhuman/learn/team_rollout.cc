#include "simhuman/learn/team_rollout.h"

#include <vector>

#include "simhuman/learn/gae.h"

namespace simhuman::learn {

CriticInput::CriticInput(int state_dim, int num_agents, int obs_dim, bool with_obs)
    : state_norm_(state_dim), num_agents_(num_agents), obs_dim_(obs_dim), with_obs_(with_obs) {}

int CriticInput::dim() const {
  return state_norm_.dim() + num_agents_ + (with_obs_ ? obs_dim_ : 0);
}

void CriticInput::Update(const torch::Tensor& raw_states) { state_norm_.Update(raw_states); }

torch::Tensor CriticInput::Build(const torch::Tensor& raw_states,
                                 const torch::Tensor& norm_obs) const {
  const int64_t envs = raw_states.size(0);
  torch::Tensor state = state_norm_.Normalize(raw_states).repeat_interleave(num_agents_, 0);
  torch::Tensor id = torch::eye(num_agents_).repeat({envs, 1});
  if (!with_obs_) return torch::cat({state, id}, 1);
  return torch::cat({state, id, norm_obs}, 1);
}

RolloutBuffer CollectTeamRollout(MultiAgentVecEnv& env, ActorCritic& net,
                                 control::ObsNormalizer& obs_norm, CriticInput& critic_in,
                                 core::Rng& rng, int steps, float gamma,
                                 const std::function<void(const TeamEpisodeStats&)>& on_episode) {
  const int E = env.num_envs(), N = env.num_agents(), D = env.obs_dim(), A = env.act_dim();
  const int S = env.state_dim(), B = E * N;
  RolloutBuffer buf = RolloutBuffer::Make(steps, B, D, A, critic_in.dim());
  torch::NoGradGuard ng;
  net.actor->eval();
  torch::Tensor log_std = net.actor->log_std();
  torch::Tensor std_dev = torch::exp(log_std);
  auto view = [](const std::vector<float>& v, int64_t rows, int64_t cols) {
    return torch::from_blob(const_cast<float*>(v.data()), {rows, cols});
  };
  std::vector<float> actions(static_cast<size_t>(B) * A);
  for (int t = 0; t < steps; ++t) {
    torch::Tensor raw_obs = view(env.obs(), B, D), raw_state = view(env.state(), E, S);
    obs_norm.Update(raw_obs);
    critic_in.Update(raw_state);
    torch::Tensor noise = DrawGaussian(rng, B, A);
    torch::Tensor o = obs_norm.Normalize(raw_obs);
    torch::Tensor c = critic_in.Build(raw_state, o);
    torch::Tensor mean = net.actor->forward(o);
    torch::Tensor act = mean + std_dev * noise;
    buf.obs[t] = o;
    buf.critic_obs[t] = c;
    buf.act[t] = act;
    buf.logp[t] = GaussianLogProb(act, mean, log_std, net.act_used);
    buf.value[t] = net.critic->forward(c).squeeze(-1);
    torch::from_blob(actions.data(), {B, A}).copy_(act);
    env.Step(actions.data());

    torch::Tensor rew = view(env.rewards(), B, 1).squeeze(-1).clone();
    torch::Tensor done = torch::zeros({B});
    std::vector<int64_t> trunc;
    for (int i = 0; i < E; ++i) {
      const bool ended = env.terminated()[i] || env.truncated()[i];
      for (int a = 0; a < N; ++a) {
        if (ended) done[i * N + a] = 1.f;
        if (env.truncated()[i]) trunc.push_back(static_cast<int64_t>(i) * N + a);
      }
    }
    // time limits: bootstrap each agent with the critic's value of the terminal state
    if (!trunc.empty()) {
      torch::Tensor term_c = critic_in.Build(view(env.terminal_state(), E, S),
                                             obs_norm.Normalize(view(env.terminal_obs(), B, D)));
      torch::Tensor idx = torch::tensor(trunc, torch::kInt64);
      torch::Tensor v = net.critic->forward(term_c.index_select(0, idx)).squeeze(-1);
      AddTimeLimitBootstrap(rew, trunc, v, gamma);
    }
    buf.reward[t] = rew;
    buf.done[t] = done;
    for (const TeamEpisodeStats& e : env.finished()) on_episode(e);
  }
  torch::Tensor o = obs_norm.Normalize(view(env.obs(), B, D));
  buf.last_value = net.critic->forward(critic_in.Build(view(env.state(), E, S), o)).squeeze(-1);
  return buf;
}

}  // namespace simhuman::learn
