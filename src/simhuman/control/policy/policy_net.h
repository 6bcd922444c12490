#pragma once
/// LibTorch pieces shared by training (learn/) and inference (PolicyController): the Gaussian
/// MLP actor, the value MLP, the running observation normalizer, and the policy file format.
/// Includes torch: include it only from .cc files of learn/ and control/policy/.
///
/// Policy file (a torch::serialize archive, written by learn::ExportPolicy or a checkpoint):
///   "format" = "simhuman-policy-v1", "task" (string), "obs_dim", "act_dim" (int),
///   "hidden" (int64 tensor of layer widths), "actor" (module archive),
///   "obs_mean", "obs_var" (float64 tensors), "obs_count" (double), "obs_clip" (double),
///   optionally "variant" (string; PolicyMeta::variant).
/// Checkpoints hold the same keys plus the training state (see learn/ppo.h).

#include <torch/torch.h>

#include <functional>
#include <string>
#include <vector>

#include "simhuman/core/status.h"

namespace simhuman::control {

inline constexpr char kPolicyFormat[] = "simhuman-policy-v1";

/// Linear+ELU layers of `hidden` widths, then a linear output layer whose weights are scaled
/// by `out_gain` at initialisation.
torch::nn::Sequential MakeMlp(int in, const std::vector<int>& hidden, int out, double out_gain);

/// A diagonal Gaussian policy: mean = MLP(obs), state-independent log std (clamped).
class GaussianActorImpl : public torch::nn::Module {
 public:
  GaussianActorImpl(int obs_dim, int act_dim, const std::vector<int>& hidden, double init_std);
  /// Mean action for normalized observations [B, obs_dim].
  torch::Tensor forward(const torch::Tensor& obs);
  /// Log std [act_dim], clamped to [log 0.05, log 1].
  torch::Tensor log_std() const;

 private:
  torch::nn::Sequential net_{nullptr};
  torch::Tensor log_std_;
};
TORCH_MODULE(GaussianActor);

/// Running mean/variance of observations (float64 statistics, merged per batch).
class ObsNormalizer {
 public:
  explicit ObsNormalizer(int dim = 0, double clip = 5.0);
  /// Adds a batch [B, dim] (float32) to the statistics.
  void Update(const torch::Tensor& batch);
  /// (x - mean) / sqrt(var + eps), clipped to +-clip; float32 [B, dim].
  torch::Tensor Normalize(const torch::Tensor& x) const;
  void Save(torch::serialize::OutputArchive& ar) const;
  /// Errors if keys are missing or the dimension differs from `dim`.
  absl::Status Load(torch::serialize::InputArchive& ar, int dim);
  /// Adds statistics of `n` samples (float64 [dim] mean and population variance), as if
  /// those samples had been passed to Update (Chan et al.'s parallel merge).
  void Merge(double n, const torch::Tensor& mean, const torch::Tensor& var);
  int dim() const { return dim_; }
  double count() const { return count_; }
  /// A normalizer over `new_dim` >= dim() inputs (to widen a policy's input): the first dim()
  /// keep their statistics and count, the new ones read as already normalized (mean 0,
  /// variance 1, with the same weight). Keeping the count keeps the inputs the policy was
  /// trained on normalized as before; a cap that let the new entries adapt also let the old
  /// ones drift, and a walking policy widened that way fell within a second.
  ObsNormalizer Widened(int new_dim) const;
  const torch::Tensor& mean() const { return mean_; }  ///< float64 [dim]
  const torch::Tensor& var() const { return var_; }    ///< float64 [dim], population variance

 private:
  int dim_;
  double clip_;
  torch::Tensor mean_, var_;  // float64
  double count_ = 0;
  torch::Tensor mean_f_, std_f_;  // cached float32
  void Cache();
};

/// Metadata of a policy file.
struct PolicyMeta {
  std::string task;
  int obs_dim = 0, act_dim = 0;
  std::vector<int> hidden;
  /// The task's variant the policy was trained under (walk: the gait, control::WalkGait);
  /// key "variant", absent in older files: "".
  std::string variant;
  /// carry: trained with gripping hands (world kind "humanoid_grip"); key "carry_grip",
  /// written only when true
  bool carry_grip = false;
};

/// Writes the policy keys (format, meta, actor, normalizer) into `ar`.
void SavePolicyKeys(torch::serialize::OutputArchive& ar, const PolicyMeta& meta,
                    GaussianActor& actor, const ObsNormalizer& norm);

/// Loads a policy file or checkpoint at `path`. Errors name the file and what is wrong
/// (missing, not a policy archive, wrong task or dimensions).
struct LoadedPolicy {
  PolicyMeta meta;
  GaussianActor actor{nullptr};
  ObsNormalizer norm;
};
core::StatusOr<LoadedPolicy> LoadPolicyFile(const std::string& path);

/// InvalidArgument unless `loaded` (read from `path`) is a policy of one of `tasks` with `obs_dim`
/// observations and `act_dim` actions; the error names the file, what it holds, what the `stage`
/// needs, the task to train (the last of `tasks`) and `use_instead`.
absl::Status CheckPolicyKind(const LoadedPolicy& loaded, const std::string& path,
                             const std::string& stage, const std::vector<std::string>& tasks,
                             int obs_dim, int act_dim, const std::string& use_instead);

/// The policy's mean action for one observation (meta.obs_dim floats in, meta.act_dim out):
/// zeros for a non-finite observation or a Torch error. Not thread-safe.
std::function<void(const float* obs, float* act)> MeanActionFn(LoadedPolicy policy);

/// Reads the metadata keys from an open archive.
core::StatusOr<PolicyMeta> ReadPolicyMeta(torch::serialize::InputArchive& ar);

}  // namespace simhuman::control
