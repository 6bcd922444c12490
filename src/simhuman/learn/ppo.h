#pragma once
/// PPO in LibTorch on a VecEnv: clipped surrogate, GAE(gamma, lambda), clipped value loss,
/// entropy bonus, Adam with a linearly decaying learning rate, minibatch epochs, gradient-norm
/// clipping, running observation normalization, NaN guards, atomic checkpoints and resume.
/// This header is torch-free (the trainer is a pimpl); only app/ drives it and prints.
/// The stages are shared with MappoTrainer (learn/mappo.h): collection (learn/ppo_rollout.h),
/// GAE (learn/gae.h), the policy/value update and non-finite guard (learn/ppo_update.h), the
/// AMP stage (learn/ppo_amp.h) and checkpoint pieces (learn/ppo_checkpoint.h).
///
/// AMP: with `amp_clips` set, the task's AMP features (VecTask::AmpClipFeatures) of the clips
/// are the expert data of a discriminator (learn/amp.h) trained after each PPO update on
/// agent pairs from a replay buffer; its weights, normalizer and Adam state are part of the
/// checkpoint, and resuming an AMP run from a checkpoint without them is DataLoss (the replay
/// buffer is not saved: it refills from the first iteration after a resume).
///
/// Run folder `out/`: config.json (resolved config), log.jsonl (one line per iteration),
/// checkpoint.pt (everything needed to resume), policy.pt (latest policy export) and
/// best_policy.pt (the export with the best recent success rate).
///
/// Reproducibility: networks are initialised from torch::manual_seed(seed); action noise and
/// minibatch shuffles come from a seeded core::Rng stored in the checkpoint; env episodes are
/// seeded per (seed, env, episode). With the same seed and thread count a run repeats.
///
/// Data-parallel (DD-PPO, learn/data_parallel.h): given a communicator of K ranks, every rank
/// steps its own num_envs environments (seeded per rank), gradients are averaged and the
/// normaliser merged over the ranks, episode counts and the curriculum are global, env_steps
/// counts the steps of all ranks, and only rank 0 writes files (its episodes make the
/// logged statistics). A checkpoint holds nothing rank-specific but rank 0's RNG, so a run
/// resumes on any K; the same seed and K repeat a run. AMP runs on one rank only.

#include <cstdint>
#include <memory>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "simhuman/core/communicator.h"
#include "simhuman/core/status.h"
#include "simhuman/learn/ppo_config.h"

namespace simhuman::learn {

class VecTask;

/// What one iteration did (episode statistics over the last 200 finished episodes).
struct IterationStats {
  int64_t iteration = 0;
  int64_t env_steps = 0;
  double wall_s = 0;  ///< training wall time, summed over sessions
  double mean_return = 0, mean_length = 0, success_rate = 0, fall_rate = 0;
  int64_t episodes = 0;  ///< finished so far
  double policy_loss = 0, value_loss = 0, entropy = 0, approx_kl = 0, clip_frac = 0;
  double lr = 0, action_std = 0, curriculum = 0;
  double steps_per_s = 0, collect_s = 0, update_s = 0;
  int skipped_minibatches = 0;
  int stepped_minibatches = 0;  ///< minibatches that stepped (fewer after a target_kl stop)
  bool checkpointed = false;
  // AMP (logged only when AMP is on): discriminator loss and gradient penalty, accuracy and
  // mean D on expert and agent pairs (means over the iteration's discriminator updates), and
  // the rollout's mean style and task rewards (before the weights).
  bool amp = false;
  double amp_disc_loss = 0, amp_grad_penalty = 0, amp_expert_acc = 0, amp_agent_acc = 0;
  double amp_d_expert = 0, amp_d_agent = 0, amp_style_reward = 0, amp_task_reward = 0;
  int amp_skipped = 0;
  // data-parallel runs (logged when ranks > 1), on rank 0: the update's gradient allreduces
  // (calls, payload bytes per rank, seconds inside them), and `sync_s`, the seconds in the
  // allreduces right after the rollout (normaliser, counts): mostly the wait for the slowest
  // rank's rollout
  int ranks = 1;
  int64_t allreduce_calls = 0, allreduce_bytes = 0;
  double allreduce_s = 0, sync_s = 0;
  /// Every rank's own rollout time (s, before any wait), by rank: their spread is the wait a
  /// synchronous step costs (the scaling model's input, docs/SCALING.md).
  std::vector<double> rank_rollout_s;
  nlohmann::json ToJson() const;
};

class PpoTrainer {
 public:
  /// Starts a new run writing to `out_dir` (created). AlreadyExists if it holds a checkpoint.
  /// `comm` (not owned, may be null: one process) makes the run data-parallel; Create and
  /// Resume make no collective calls, so the caller agrees on their result (core::AgreeOk).
  static core::StatusOr<std::unique_ptr<PpoTrainer>> Create(const PpoConfig& config,
                                                            const std::string& out_dir,
                                                            core::Communicator* comm = nullptr);
  /// As Create, with a caller-made task (tests; config.task only names it in files).
  static core::StatusOr<std::unique_ptr<PpoTrainer>> CreateWithTask(
      const PpoConfig& config, const std::string& out_dir, std::unique_ptr<VecTask> task,
      core::Communicator* comm = nullptr);
  /// Continues the run in `out_dir` from its checkpoint. A missing checkpoint is NotFound and a
  /// corrupt one DataLoss (never a silent restart). `total_steps` > 0 overrides the target;
  /// `changes` (a JSON object, PpoConfig::WithResumeChanges) changes the run's schedule keys from
  /// here on, and the next checkpoint stores them.
  static core::StatusOr<std::unique_ptr<PpoTrainer>> Resume(
      const std::string& out_dir, int64_t total_steps = 0, core::Communicator* comm = nullptr,
      const nlohmann::json& changes = nlohmann::json::object());
  ~PpoTrainer();

  /// Collects one rollout and updates; collective with a communicator. Errors: too many
  /// non-finite updates in a row, I/O (rank 0), the communicator's.
  core::StatusOr<IterationStats> Iterate();
  /// Writes checkpoint.pt and policy.pt atomically (and best_policy.pt when better); on ranks
  /// other than 0 it writes nothing.
  absl::Status Checkpoint();
  bool done() const;
  int64_t env_steps() const;
  const PpoConfig& config() const;
  const std::string& out_dir() const;

  struct Impl;

 private:
  explicit PpoTrainer(std::unique_ptr<Impl> impl);
  std::unique_ptr<Impl> impl_;
};

/// Copies the policy keys of a checkpoint or policy file into a small policy file at `out`
/// (atomic). Errors name the file.
absl::Status ExportPolicy(const std::string& checkpoint, const std::string& out);

/// (env_steps, training wall seconds) stored in a checkpoint or policy file (wall 0 when the
/// file holds none). Errors name the file.
core::StatusOr<std::pair<int64_t, double>> ReadCheckpointProgress(const std::string& path);

/// A new training task by name (the names PpoConfig::task accepts, e.g. "walk", "reach") with
/// `num_envs` copies; `physics_solver` "newton" or "pgs" (MuJoCo tasks; others ignore it);
/// `walk_gait` the walk and carry tasks' reference gait (control::WalkGait; a policy file
/// records the one it was trained with). InvalidArgument listing the valid names for an
/// unknown task or gait; model-building errors.
core::StatusOr<std::unique_ptr<VecTask>> MakeVecTask(const std::string& name, int num_envs,
                                                     const std::string& physics_solver,
                                                     const std::string& walk_gait = "");

}  // namespace simhuman::learn
