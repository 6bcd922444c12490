#pragma once
/// The collection stage of MAPPO: a shared Gaussian actor acting on every agent's own
/// observation of a MultiAgentVecEnv, and a centralised critic on the env's shared state plus
/// the agent's one-hot id (and, optionally, the agent's observation). Rows of the rollout are
/// env-agent pairs, env-major (row i * N + a).
///
/// Includes torch: include it only from learn/*.cc and learn tests.
/// Thread-safety: none; the trainer thread uses it.

#include <torch/torch.h>

#include <functional>

#include "simhuman/control/policy/policy_net.h"
#include "simhuman/core/rng.h"
#include "simhuman/learn/multi_agent_env.h"
#include "simhuman/learn/ppo_rollout.h"
#include "simhuman/learn/ppo_update.h"

namespace simhuman::learn {

/// The centralised critic's input of each agent: [normalized shared state (S), one-hot agent
/// id (N), normalized own observation (D, with `with_obs`)]. The state's running normalizer
/// lives here; the observation's is the actor's.
class CriticInput {
 public:
  CriticInput() = default;
  CriticInput(int state_dim, int num_agents, int obs_dim, bool with_obs);
  /// Floats per critic input.
  int dim() const;
  /// Adds raw states [E, S] to the state statistics.
  void Update(const torch::Tensor& raw_states);
  /// Critic inputs [E * N, dim()] from raw states [E, S] and normalized observations
  /// [E * N, D].
  torch::Tensor Build(const torch::Tensor& raw_states, const torch::Tensor& norm_obs) const;
  control::ObsNormalizer& state_norm() { return state_norm_; }

 private:
  control::ObsNormalizer state_norm_;
  int num_agents_ = 0, obs_dim_ = 0;
  bool with_obs_ = true;
};

/// Runs the shared actor with Gaussian exploration noise (drawn from `rng` in row order) on
/// every agent of `env` for `steps` steps: updates `obs_norm` and the critic's state
/// statistics with each step's raw inputs, records each agent's normalized observation, critic
/// input, action, log-probability, value and own reward (plus gamma V(terminal) at time
/// limits), the env's done flag on each of its agents' rows, and calls `on_episode` for every
/// finished team episode in env order.
RolloutBuffer CollectTeamRollout(MultiAgentVecEnv& env, ActorCritic& net,
                                 control::ObsNormalizer& obs_norm, CriticInput& critic_in,
                                 core::Rng& rng, int steps, float gamma,
                                 const std::function<void(const TeamEpisodeStats&)>& on_episode);

}  // namespace simhuman::learn
