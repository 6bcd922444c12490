#pragma once
/// The AMP stage of PpoTrainer (learn/amp.h): during a rollout it mixes the discriminator's
/// style reward into the task reward and keeps the step's (s_t, s_t+1) feature pairs; after the
/// PPO update it adds them to the replay buffer and trains the discriminator. Its weights and
/// Adam state go into the checkpoint (keys "amp_disc", "amp_optim").
///
/// Includes torch: include it only from learn/*.cc and learn tests.
/// Thread-safety: none; the trainer thread uses it.

#include <torch/torch.h>

#include <memory>
#include <string>

#include "simhuman/core/rng.h"
#include "simhuman/core/status.h"
#include "simhuman/learn/amp.h"
#include "simhuman/learn/ppo_config.h"

namespace simhuman::learn {

class VecEnv;
struct IterationStats;

class AmpStage {
 public:
  /// Loads `config.amp_clips`, turns on the env's AMP feature pairs (call before its
  /// ResetAll) and builds the discriminator (its initial weights come from torch's global
  /// generator). Null when amp_clips is empty. Errors name the clip or say why the task has no
  /// AMP features.
  static core::StatusOr<std::unique_ptr<AmpStage>> Create(const PpoConfig& config, VecEnv& env);

  /// Starts a rollout of `steps` steps over `envs` envs.
  void BeginRollout(int steps, int envs);
  /// Step `t`'s reward: amp_task_weight * task_reward + amp_style_weight * r_style of the
  /// env's feature pairs `pairs` ([envs x 2F], copied).
  torch::Tensor MixReward(int t, const torch::Tensor& task_reward, const float* pairs);
  /// After the PPO update: the rollout's pairs into the replay buffer, then amp_disc_updates
  /// discriminator minibatches (samples drawn from `rng`); fills the amp_* fields of `stats`.
  void Update(core::Rng& rng, IterationStats* stats);

  /// Writes "amp_disc" and "amp_optim" into a checkpoint archive.
  void Save(torch::serialize::OutputArchive& ar);
  /// Reads them; DataLoss naming `path` when absent.
  absl::Status Load(torch::serialize::InputArchive& ar, const std::string& path);

 private:
  AmpStage() = default;
  PpoConfig cfg_;
  int feature_dim_ = 0;
  AmpDiscriminator disc_{nullptr};
  std::unique_ptr<torch::optim::Adam> opt_;
  torch::Tensor expert_;  // [M, 2F] expert pairs
  std::unique_ptr<AmpReplayBuffer> replay_;
  torch::Tensor pairs_;  // [T, E, 2F] this rollout's agent pairs
  double style_sum_ = 0, task_sum_ = 0;
};

}  // namespace simhuman::learn
