#pragma once
/// The PPO trainer's configuration: one strict struct, read from and written to JSON.

#include <cstdint>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "simhuman/core/status.h"

namespace simhuman::learn {

/// Training configuration (strict JSON: unknown keys are errors).
struct PpoConfig {
  std::string task = "walk";  ///< "walk" or "reach"
  int64_t total_steps = 30'000'000;
  int num_envs = 128;
  int threads = 2;        ///< env worker threads
  int torch_threads = 1;  ///< LibTorch intra-op threads while collecting (env threads run then)
  /// LibTorch intra-op threads for the PPO and AMP updates, when the env threads are idle
  /// (2 on 2 quiet cores: the update is 1.5x faster; on a busy machine 1 can be faster)
  int update_torch_threads = 2;
  /// Collection splits the envs into this many chunks; each worker runs the policy on a chunk
  /// and steps it at once, so inference runs on every core and overlaps physics
  /// (VecEnv::StepChunked). 0: the whole batch is inferred on the calling thread, then stepped.
  int rollout_chunks = 0;
  /// MuJoCo solver of the training physics: "newton" (as at run time), "pgs" (walk task only;
  /// a cheaper solve of the same contact problem, about 1.3x faster env steps; policies move
  /// between the two: docs/BENCHMARKS.md) or "auto" (default: pgs for walk, newton otherwise).
  std::string physics_solver = "auto";
  /// Length scales of the humans the envs hold (walk task only), spread evenly over the envs:
  /// e.g. [0.6, 0.8, 1.0, 1.2] trains one policy for children to tall adults (the walk task
  /// works in the adult's units, control::WalkScale). Each in [0.5, 1.5].
  std::vector<double> body_scales = {1.0};
  /// The walk and carry tasks' reference gait (control::WalkGait: "" the original, "human");
  /// recorded in the policy file, which then runs with it. A carry run started from a walking
  /// policy (init_from) must name that policy's gait.
  std::string walk_gait;
  /// carry task: the human's hands grip the box while they hold it (world kind
  /// "humanoid_grip"); recorded in the policy file
  bool carry_grip = false;
  /// carry task: the share of training episodes that start holding the box in the carry phase
  /// (reference-state initialisation), in [0, 1]; the default is
  /// learn::CarryTask::kDefaultHeldStartFraction. Evaluation always walks up to the box.
  double carry_held_start_frac = 0.35;
  /// carry task: the share of training episodes that start part-way into the put-down's squat
  /// (reference-state initialisation), in [0, 1]; the held share applies to the others. The
  /// default is learn::CarryTask::kDefaultPutDownStartFraction. Evaluation never does.
  double carry_put_down_start_frac = 0.0;
  /// walk task's reward: the leg gait term's weight and width (rad^2), the foot-slip weight
  double walk_gait_weight = 1.0;
  double walk_gait_width = 0.5;
  double walk_foot_slip_weight = 0.5;
  double walk_route_share = 0.0;  ///< walk: share of targets at the end of a random route
  uint64_t seed = 1;
  int rollout_steps = 32;  ///< per env per iteration
  int epochs = 3;
  int minibatches = 4;
  double lr = 3e-4;
  double lr_final_frac = 0.3;  ///< lr decays linearly to lr * this at total_steps
  double gamma = 0.99, lambda = 0.95;
  double clip = 0.2;
  double value_clip = 1.0;  ///< absolute range around the old value prediction
  double value_coef = 0.5;
  double entropy_coef = 0.001;
  double max_grad_norm = 1.0;
  double target_kl = 0;  ///< PPO epochs stop once a minibatch KL exceeds 1.5x this (0: off)
  double init_std = 0.5;
  std::vector<int> hidden = {256, 128};  ///< actor (policy) layer widths
  /// Value-network layer widths; empty: the same as `hidden`. The critic is not shipped, and a
  /// narrower one makes the update cheaper. (Defaults since session 7: 3 epochs, actor 256-128,
  /// critic 128-128 bring the walk training loop to about 10 k env steps/s on 2 quiet cores.)
  std::vector<int> critic_hidden = {128, 128};
  /// A new run starts its policy (actor weights, action std and observation normalizer) from
  /// this policy file or checkpoint instead of random weights (fine-tuning); the value network
  /// starts fresh. Its task and sizes must match. Empty: random initialization.
  std::string init_from;
  /// With init_from: the first this many iterations train only the value network, so the
  /// fresh critic's advantages do not wreck the policy it was given.
  int critic_warmup_iters = 20;
  double checkpoint_every_s = 180;
  int max_bad_updates = 5;  ///< abort after this many non-finite updates in a row
  /// The curriculum level rises by 1/9 when more than half of >= 64 recent episodes succeed,
  /// and at the latest after this many env steps at one level (0: only on success).
  int64_t curriculum_max_steps = 400'000;

  // AMP (learn/amp.h): off while amp_clips is empty. Rewards become
  // amp_task_weight * r_task + amp_style_weight * r_style, r_style in [0, 1].
  std::vector<std::string> amp_clips;  ///< clip files (.clip.json) or BVH files (.bvh)
  double amp_task_weight = 1.0;        ///< w_G
  double amp_style_weight = 0.5;       ///< w_S
  double amp_grad_penalty = 5.0;       ///< w_gp of (w_gp / 2) E_expert ||dD/dx||^2
  std::vector<int> amp_disc_hidden = {256, 256};
  double amp_disc_lr = 3e-4;
  int amp_disc_batch = 512;         ///< expert and agent pairs per discriminator minibatch
  int amp_disc_updates = 8;         ///< discriminator minibatches per iteration
  int64_t amp_replay_size = 65536;  ///< agent pairs kept for discriminator training

  /// Every field in range (one field table, ppo_config.cc, drives Validate, ToJson and
  /// FromJson), then the checks between fields; the message names the key, its value and what
  /// is valid.
  absl::Status Validate() const;
  /// Every key.
  nlohmann::json ToJson() const;
  /// Strict: an unknown key is InvalidArgument naming it and listing the valid keys, a wrong
  /// type one naming its JSON pointer and the expected type, a bad value one from Validate();
  /// missing keys keep defaults.
  static core::StatusOr<PpoConfig> FromJson(const nlohmann::json& j);
  /// FromJson for the config stored in a checkpoint. Keys added after the checkpoint was
  /// written take the value that reproduces what that run built, not today's default: a
  /// config without `critic_hidden` (before session 7) had a critic as wide as `hidden`.
  static core::StatusOr<PpoConfig> FromCheckpointJson(const nlohmann::json& j);
  /// The keys a resumed run may change (its schedule, budgets and episode starts; never the
  /// task, the networks, the envs or the seed): ResumableKeys() lists them.
  static const std::vector<std::string>& ResumableKeys();
  /// `stored` (a checkpoint's config JSON) with `changes` applied: every key of `changes` must
  /// be one of ResumableKeys(), and the result is read and checked as FromCheckpointJson does.
  /// InvalidArgument names a key that may not change and lists those that may.
  static core::StatusOr<PpoConfig> WithResumeChanges(const nlohmann::json& stored,
                                                     const nlohmann::json& changes);
};

}  // namespace simhuman::learn
