#pragma once
/// Checkpoint pieces shared by PpoTrainer and MappoTrainer: atomic archive writes, the training
/// counters, the learner state (critic, Adam, RNG; the actor goes in with the policy keys of
/// control/policy/policy_net.h), weight checks on resume and the run log. Key names are those
/// of docs/FORMATS.md ("Training checkpoints").
///
/// Includes torch: include it only from learn/*.cc and learn tests.

#include <torch/torch.h>

#include <cstdint>
#include <nlohmann/json.hpp>
#include <string>

#include "simhuman/core/rng.h"
#include "simhuman/core/status.h"
#include "simhuman/learn/ppo_update.h"

namespace simhuman::learn {

/// Writes `ar` to `path` through `path`.tmp and a rename. PermissionDenied names the file.
absl::Status SaveArchiveAtomic(torch::serialize::OutputArchive& ar, const std::string& path);

/// The counters a trainer checkpoints ("iteration", "env_steps", "episodes", "wall_s",
/// "best_success").
struct TrainingProgress {
  int64_t iteration = 0, env_steps = 0, episodes = 0;
  double wall_s = 0;         ///< training wall time, summed over sessions
  double best_success = -1;  ///< success rate of the last best_policy.pt
  void Write(torch::serialize::OutputArchive& ar) const;
  /// False when a key is missing.
  bool Read(torch::serialize::InputArchive& ar);
};

/// Writes "critic", "optim" and "rng" (the engine state as text).
void WriteLearnerState(torch::serialize::OutputArchive& ar, ActorCritic& net, core::Rng& rng);

/// Loads "actor", "critic" (its shapes must be those `net` was built with), "optim" and "rng".
/// DataLoss naming `path` when something is missing or of another shape.
absl::Status ReadLearnerState(torch::serialize::InputArchive& ar, const std::string& path,
                              ActorCritic& net, core::Rng& rng);

/// DataLoss naming `path` when a weight of `net` is not finite.
absl::Status CheckFiniteWeights(const ActorCritic& net, const std::string& path);

/// Appends one JSON line to `path`.
void AppendJsonLine(const std::string& path, const nlohmann::json& line);

/// Drops the lines of the log at `path` whose "env_steps" exceed `env_steps` (iterations
/// logged after the checkpoint a run resumes from); a missing log stays missing.
void TrimLogAfter(const std::string& path, int64_t env_steps);

}  // namespace simhuman::learn
