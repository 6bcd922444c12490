#pragma once
/// Multi-agent PPO (MAPPO, Yu et al. 2022) on a MultiAgentVecEnv: centralised training with
/// decentralised execution. One Gaussian actor is shared by the agents and acts on each
/// agent's own observation; a centralised critic values each agent from the env's shared
/// state, the agent's one-hot id and (critic_agent_obs) its observation. Each agent learns
/// from its own reward with GAE per agent. The stages are PpoTrainer's (learn/ppo_update.h,
/// learn/gae.h, learn/ppo_checkpoint.h); only the collection differs (learn/team_rollout.h).
/// This header is torch-free (the trainer is a pimpl).
///
/// Run folder `out/`: config.json (resolved MappoConfig), log.jsonl (IterationStats lines as
/// PpoTrainer writes them; env_steps count team steps, return is the mean agent return),
/// checkpoint.pt (everything needed to resume; docs/FORMATS.md) and policy.pt (the shared
/// actor as a policy file: every agent runs it on its own observation).
///
/// Reproducibility: networks from torch::manual_seed(seed); action noise and minibatch
/// shuffles from a seeded core::Rng stored in the checkpoint; env episodes seeded per (seed,
/// env, episode). With the same seed and thread count a run repeats.

#include <cstdint>
#include <memory>
#include <string>

#include "simhuman/core/status.h"
#include "simhuman/learn/mappo_config.h"
#include "simhuman/learn/ppo.h"

namespace simhuman::learn {

class MultiAgentVecTask;

class MappoTrainer {
 public:
  /// Starts a new run of the registered task config.task (learn/multi_agent_tasks.h) writing
  /// to `out_dir` (created). AlreadyExists if it holds a checkpoint.
  static core::StatusOr<std::unique_ptr<MappoTrainer>> Create(const MappoConfig& config,
                                                              const std::string& out_dir);
  /// As Create, with a caller-made task (tests); its team size must be config.num_agents.
  static core::StatusOr<std::unique_ptr<MappoTrainer>> CreateWithTask(
      const MappoConfig& config, const std::string& out_dir,
      std::unique_ptr<MultiAgentVecTask> task);
  /// Continues the run in `out_dir` from its checkpoint. A missing checkpoint is NotFound and a
  /// corrupt one DataLoss. `total_steps` > 0 overrides the target.
  static core::StatusOr<std::unique_ptr<MappoTrainer>> Resume(const std::string& out_dir,
                                                              int64_t total_steps = 0);
  ~MappoTrainer();

  /// Collects one team rollout and updates. Errors: too many non-finite updates in a row, I/O.
  core::StatusOr<IterationStats> Iterate();
  /// Writes checkpoint.pt and policy.pt atomically.
  absl::Status Checkpoint();
  bool done() const;
  int64_t env_steps() const;
  const MappoConfig& config() const;
  const std::string& out_dir() const;

  struct Impl;

 private:
  explicit MappoTrainer(std::unique_ptr<Impl> impl);
  std::unique_ptr<Impl> impl_;
};

}  // namespace simhuman::learn
