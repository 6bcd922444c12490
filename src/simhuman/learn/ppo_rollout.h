#pragma once
/// The collection stage of PPO: rollout buffers, the window of recent episodes, and the
/// rollout of a Gaussian policy on a VecEnv (PpoTrainer); MappoTrainer collects its team
/// rollouts into the same buffers (learn/mappo.cc).
///
/// Includes torch: include it only from learn/*.cc and learn tests.
/// Thread-safety: none, except that CollectVecRollout runs the policy on the env's workers.

#include <torch/torch.h>

#include <deque>
#include <functional>

#include "simhuman/control/policy/policy_net.h"
#include "simhuman/core/rng.h"
#include "simhuman/learn/ppo_update.h"
#include "simhuman/learn/vec_env.h"

namespace simhuman::learn {

class AmpStage;

/// One rollout of T steps over B rows (envs, or env-agent pairs), time-major.
struct RolloutBuffer {
  torch::Tensor obs;         ///< [T, B, D] normalized actor inputs
  torch::Tensor critic_obs;  ///< [T, B, C] critic inputs; undefined: the critic reads obs
  torch::Tensor act;         ///< [T, B, A]
  torch::Tensor logp;        ///< [T, B]
  torch::Tensor value;       ///< [T, B]
  torch::Tensor reward;      ///< [T, B] including time-limit bootstraps
  torch::Tensor done;        ///< [T, B] 1 where the episode ended at that step
  torch::Tensor last_value;  ///< [B] values after the last step

  /// Uninitialized buffers; `critic_dim` 0: no separate critic inputs.
  static RolloutBuffer Make(int steps, int rows, int obs_dim, int act_dim, int critic_dim = 0);
  /// GAE advantages and returns, flattened to T * B samples for PpoUpdate.
  PpoBatch Finish(float gamma, float lambda) const;
};

/// Mean statistics of the episodes in an EpisodeWindow (0 when empty).
struct EpisodeMeans {
  double ret = 0, length = 0, success = 0, fall = 0;
};

/// The last `capacity` finished episodes (PpoTrainer logs means over 200).
class EpisodeWindow {
 public:
  explicit EpisodeWindow(size_t capacity) : capacity_(capacity) {}
  void Add(const EpisodeStats& e);
  size_t size() const { return episodes_.size(); }
  EpisodeMeans Means() const;

 private:
  size_t capacity_;
  std::deque<EpisodeStats> episodes_;
};

/// What CollectVecRollout needs besides the env.
struct VecRolloutOptions {
  int steps = 32;       ///< T
  float gamma = 0.99f;  ///< for the time-limit bootstrap
  /// >0: VecEnv::StepChunked with this many chunks (the policy runs on the env's workers);
  /// 0: the whole batch is inferred on the calling thread, then stepped.
  int chunks = 0;
};

/// Runs the actor with Gaussian exploration noise (drawn from `rng` in env order, so results
/// do not depend on chunks) on `env` for `options.steps` steps: updates `norm` with each
/// step's raw observations, records normalized observations, actions, log-probabilities,
/// values, rewards (mixed with the style reward by `amp` when given, plus gamma V(terminal
/// observation) at time limits) and dones, and calls `on_episode` for every finished episode in
/// env order.
RolloutBuffer CollectVecRollout(VecEnv& env, ActorCritic& net, control::ObsNormalizer& norm,
                                core::Rng& rng, AmpStage* amp, const VecRolloutOptions& options,
                                const std::function<void(const EpisodeStats&)>& on_episode);

}  // namespace simhuman::learn
