#pragma once
/// Adversarial motion priors (AMP, Peng et al. 2021; as UniHSI and CooHOI use it) in LibTorch:
/// a discriminator on (s_t, s_t+1) pairs of AMP features (learn/amp_features.h), trained with
/// the least-squares loss and a gradient penalty on expert samples, the style reward
/// r_S = max(0, 1 - 0.25 (D - 1)^2), expert pairs from motion clips and a replay buffer of
/// agent pairs. PpoTrainer mixes r = w_G r_task + w_S r_S (see PpoConfig's amp_* keys).
///
/// Includes torch: include it only from learn/*.cc and learn tests.
/// Thread-safety: none; one trainer thread uses these objects.

#include <torch/torch.h>

#include <vector>

#include "simhuman/core/rng.h"
#include "simhuman/core/status.h"

namespace simhuman::learn {

/// What one discriminator update round measured (means over its minibatches).
struct AmpUpdateStats {
  double loss = 0;                   ///< least-squares loss + gradient penalty term
  double grad_penalty = 0;           ///< E_expert ||dD/dx||^2 (before the weight)
  double expert_acc = 0;             ///< fraction of expert pairs with D > 0
  double agent_acc = 0;              ///< fraction of agent pairs with D < 0
  double d_expert = 0, d_agent = 0;  ///< mean D
};

/// The discriminator network: inputs are pairs [B, 2F] of raw features, normalized inside by
/// the expert statistics (buffers "feat_mean", "feat_std", saved with the module), then an ELU
/// MLP with one linear output.
class AmpDiscriminatorImpl : public torch::nn::Module {
 public:
  AmpDiscriminatorImpl(int feature_dim, const std::vector<int>& hidden);
  /// Sets the normalization from expert features [N, F] (std floored at 0.05).
  void FitNormalizer(const torch::Tensor& expert_features);
  /// Normalized pairs [B, 2F] (clipped to +-10).
  torch::Tensor Normalize(const torch::Tensor& pairs) const;
  /// D of normalized pairs [B, 2F] -> [B].
  torch::Tensor forward(const torch::Tensor& normalized_pairs);
  int feature_dim() const { return feature_dim_; }

 private:
  int feature_dim_;
  torch::nn::Sequential net_{nullptr};
  torch::Tensor mean_, std_;
};
TORCH_MODULE(AmpDiscriminator);

/// Style reward max(0, 1 - 0.25 (D - 1)^2) of raw pairs [B, 2F] -> [B] (no gradient). Also
/// returns D through `d_out` when given.
torch::Tensor AmpStyleReward(AmpDiscriminator& disc, const torch::Tensor& pairs,
                             torch::Tensor* d_out = nullptr);

/// Expert (s_t, s_t+1) pairs of consecutive frames of each clip: `clip_features` holds one
/// [frames x F] row-major array per clip (clips of fewer than 2 frames add nothing).
torch::Tensor AmpExpertPairs(const std::vector<std::vector<float>>& clip_features, int feature_dim);

/// A ring buffer of agent pairs [capacity, 2F].
class AmpReplayBuffer {
 public:
  AmpReplayBuffer(int64_t capacity, int pair_dim);
  /// Appends rows of `pairs` [N, 2F], overwriting the oldest when full.
  void Add(const torch::Tensor& pairs);
  /// `n` rows drawn uniformly with replacement (size() must be > 0).
  torch::Tensor Sample(int64_t n, core::Rng& rng) const;
  int64_t size() const { return size_; }

 private:
  torch::Tensor data_;
  int64_t next_ = 0, size_ = 0;
};

/// `n` rows of `data` drawn uniformly with replacement.
torch::Tensor SampleRows(const torch::Tensor& data, int64_t n, core::Rng& rng);

/// One least-squares update: E_expert[(D - 1)^2] and E_agent[(D + 1)^2] (averaged), plus
/// (grad_penalty / 2) E_expert ||dD/dx||^2 with x the normalized expert pair (AMP's Eq. 8).
/// Skips the step (returns false) when the loss or the gradient is not finite.
bool AmpUpdate(AmpDiscriminator& disc, torch::optim::Optimizer& opt, const torch::Tensor& expert,
               const torch::Tensor& agent, double grad_penalty, double max_grad_norm,
               AmpUpdateStats* stats);

}  // namespace simhuman::learn
