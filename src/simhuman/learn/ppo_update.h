#pragma once
/// The learning stages of PPO, shared by PpoTrainer (one agent per env) and MappoTrainer (a
/// team per env, one actor shared by the agents, a centralised critic): the actor-critic
/// networks, the clipped-surrogate policy/value update over minibatch epochs, and the guard
/// that undoes and counts non-finite updates.
///
/// Includes torch: include it only from learn/*.cc and learn tests.
/// Thread-safety: none; one trainer thread uses these objects.

#include <torch/torch.h>

#include <cstdint>
#include <memory>
#include <vector>

#include "simhuman/control/policy/policy_net.h"
#include "simhuman/core/communicator.h"
#include "simhuman/core/rng.h"
#include "simhuman/core/status.h"

namespace simhuman::learn {

/// The networks PPO trains: a Gaussian MLP actor, an MLP value network (critic) whose input may
/// differ from the actor's (a centralised critic), and one Adam optimizer over both.
struct ActorCritic {
  control::GaussianActor actor{nullptr};
  torch::nn::Sequential critic{nullptr};
  torch::Tensor act_used;  ///< [A] 1 for action entries the task uses, 0 for ignored ones
  std::unique_ptr<torch::optim::Adam> opt;

  /// The actor's parameters, then the critic's (the optimizer's order).
  std::vector<torch::Tensor> Params() const;
  /// Mean action standard deviation over the used entries.
  double ActionStd() const;
};

/// Builds the actor (obs_dim -> act_dim, layer widths `hidden`, initial std `init_std`), then
/// the critic (critic_dim -> 1, `critic_hidden`, or `hidden` when empty) and Adam at `lr`.
/// The initial weights come from torch's global generator (seed it first); `used` holds 1 or 0
/// per action entry.
ActorCritic MakeActorCritic(int obs_dim, int critic_dim, int act_dim,
                            const std::vector<int>& hidden, const std::vector<int>& critic_hidden,
                            double init_std, double lr, const std::vector<float>& used);

/// Sets the learning rate of every parameter group of `opt`.
void SetLearningRate(torch::optim::Adam& opt, double lr);

/// Sum over the used action entries (`used`: 1 or 0 per entry) of the diagonal Gaussian log
/// density of actions `a` [B, A] with means `mean` [B, A] and log std `log_std` [A] -> [B].
torch::Tensor GaussianLogProb(const torch::Tensor& a, const torch::Tensor& mean,
                              const torch::Tensor& log_std, const torch::Tensor& used);

/// `rows` x `cols` standard normal floats drawn in row-major order from `rng` (a fresh
/// distribution per call, so the draw depends only on the engine's state).
torch::Tensor DrawGaussian(core::Rng& rng, int64_t rows, int64_t cols);

/// One rollout flattened to N samples. `critic_obs` undefined: the critic reads `obs`.
struct PpoBatch {
  torch::Tensor obs;         ///< [N, D] normalized actor inputs
  torch::Tensor critic_obs;  ///< [N, C] critic inputs, or undefined
  torch::Tensor act;         ///< [N, A] actions taken
  torch::Tensor old_logp;    ///< [N] their log-probabilities when taken
  torch::Tensor old_value;   ///< [N] value predictions when taken
  torch::Tensor ret;         ///< [N] value targets (advantages + values)
  torch::Tensor adv;         ///< [N] advantages (normalized by PpoUpdate)
};

/// Settings of one PPO update (the PpoConfig / MappoConfig keys of the same names).
struct PpoUpdateOptions {
  int epochs = 3;
  int minibatches = 4;
  double clip = 0.2;
  double value_clip = 1.0;
  double value_coef = 0.5;
  double entropy_coef = 0.001;
  double max_grad_norm = 1.0;
  bool critic_only = false;  ///< train only the value network (critic warm-up)
  /// Early stop: the epochs end once a minibatch's approximate KL to the rollout policy
  /// exceeds 1.5 x this (0: never). Keeps fine-tuning from a narrow policy stable.
  double target_kl = 0;
  /// Data-parallel PPO (learn/data_parallel.h): the gradients of each minibatch are averaged
  /// over the ranks of `comm`, and a non-finite rollout or loss on one rank skips the update
  /// or minibatch on all. Null: this process alone. Not owned.
  core::Communicator* comm = nullptr;
};

/// What one PPO update measured: means over the minibatches that stepped.
struct PpoUpdateStats {
  double policy_loss = 0, value_loss = 0, entropy = 0, approx_kl = 0, clip_frac = 0;
  int minibatches = 0;         ///< minibatches that stepped
  int skipped = 0;             ///< minibatches skipped for a non-finite loss or gradient
  bool kl_stopped = false;     ///< the epochs ended early on target_kl
  bool rollout_finite = true;  ///< false: nothing was trained (all minibatches skipped)
};

/// Normalizes the advantages, then runs `epochs` epochs of `minibatches` shuffled minibatches
/// (shuffles from `rng`) of the clipped surrogate + clipped value loss - entropy bonus, with
/// gradient-norm clipping, at the optimizer's current learning rate. A non-finite rollout
/// trains nothing; a minibatch with a non-finite loss or gradient is skipped.
PpoUpdateStats PpoUpdate(ActorCritic& net, const PpoBatch& batch, const PpoUpdateOptions& options,
                         core::Rng& rng);

/// Undoes and counts non-finite updates: Begin snapshots the weights before an update, End
/// restores them if the update left any non-finite, and counts updates that skipped anything;
/// `max_bad_in_row` bad updates in a row are an error.
class NonFiniteGuard {
 public:
  explicit NonFiniteGuard(int max_bad_in_row) : max_bad_in_row_(max_bad_in_row) {}
  void Begin(const std::vector<torch::Tensor>& params);
  /// Internal error ("training aborted: ...", naming `iteration`) at the limit.
  absl::Status End(const PpoUpdateStats& stats, int64_t iteration);
  int bad_in_row() const { return bad_in_row_; }

 private:
  int max_bad_in_row_;
  int bad_in_row_ = 0;
  std::vector<torch::Tensor> params_, backup_;
};

}  // namespace simhuman::learn
