#pragma once
/// Vectorized environments: E copies of one task stepped by a pool of worker threads, with
/// batched observations and actions, automatic resets, early termination and time limits.
/// Torch-free (float buffers); the trainer wraps them in tensors.
///
/// Determinism: env i's episode k is seeded with core::DeriveSeed(seed, i, k), so trajectories
/// do not depend on the number of threads or their scheduling.

#include <condition_variable>
#include <cstdint>
#include <functional>
#include <limits>
#include <memory>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

#include "simhuman/core/status.h"

namespace simhuman::learn {

struct MotionClip;

/// What one env step reports.
struct StepInfo {
  float reward = 0;
  bool terminated = false;  ///< ended by failure (no bootstrap)
  bool truncated = false;   ///< ended by the time limit (bootstrap with V(terminal obs))
  bool success = false;     ///< the task's success criterion has been met in this episode
};

/// One task with E independent copies. Reset/Step for distinct env indices may run
/// concurrently; calls for the same index never do.
class VecTask {
 public:
  virtual ~VecTask() = default;
  virtual std::string name() const = 0;
  virtual int num_envs() const = 0;
  virtual int obs_dim() const = 0;
  virtual int act_dim() const = 0;
  /// Starts a new episode of env i from `seed` and writes its first observation.
  virtual void Reset(int i, uint64_t seed, float* obs) = 0;
  /// Applies `action` (act_dim raw floats) to env i; writes the next observation (before any
  /// reset) and the step's outcome.
  virtual void Step(int i, const float* action, float* obs, StepInfo* info) = 0;
  /// Curriculum level in [0, 1] (tasks without one ignore it).
  virtual double curriculum() const { return 1.0; }
  virtual void set_curriculum(double) {}
  /// Whether the task uses action entry j (act_dim entries). PPO leaves unused entries out of
  /// the log-probabilities and the entropy, so their noise neither moves the ratio nor gets a
  /// gradient. Default: all used.
  virtual bool action_used(int j) const { return j >= 0 && j < act_dim(); }
  /// Actions are clipped by the task to [-action_limit(), action_limit()] (infinity: never
  /// clipped); the bounds of the action space the Python bindings describe.
  virtual double action_limit() const { return std::numeric_limits<double>::infinity(); }

  // AMP (learn/amp.h). Tasks without AMP features keep these defaults: amp_feature_dim() 0
  // and AmpClipFeatures Unimplemented, which PpoTrainer reports when amp_clips is set.

  /// Floats per AMP feature vector (0: the task has no AMP features).
  virtual int amp_feature_dim() const { return 0; }
  /// Writes env i's AMP features of its current state (after Reset or Step of env i, from the
  /// same thread; may update env i's kinematics). Only called when amp_feature_dim() > 0.
  virtual void AmpFeatures(int i, float* out);
  /// The features of `clip` resampled at the task's policy rate, [frames x dim] row-major.
  /// Unimplemented (naming the task) by default.
  virtual core::StatusOr<std::vector<float>> AmpClipFeatures(const MotionClip& clip) const;
};

/// A fixed pool of threads running index ranges (the calling thread takes part).
class WorkerPool {
 public:
  explicit WorkerPool(int threads);
  ~WorkerPool();
  WorkerPool(const WorkerPool&) = delete;
  WorkerPool& operator=(const WorkerPool&) = delete;
  /// Runs fn(i) for i in [0, n), blocking until all are done. Not reentrant.
  void ParallelFor(int n, const std::function<void(int)>& fn);
  int threads() const { return static_cast<int>(workers_.size()) + 1; }

 private:
  void Loop();
  void RunChunk();
  std::vector<std::thread> workers_;
  std::mutex mu_;
  std::condition_variable cv_, done_cv_;
  const std::function<void(int)>* fn_ = nullptr;
  int n_ = 0, next_ = 0, busy_ = 0;
  uint64_t generation_ = 0;
  bool stop_ = false;
};

/// A finished episode.
struct EpisodeStats {
  double ret = 0;
  int length = 0;
  bool success = false;
  bool terminated = false;
};

/// Batched stepping with automatic resets.
class VecEnv {
 public:
  VecEnv(std::unique_ptr<VecTask> task, int threads, uint64_t seed);
  int num_envs() const { return task_->num_envs(); }
  int obs_dim() const { return task_->obs_dim(); }
  int act_dim() const { return task_->act_dim(); }
  VecTask& task() { return *task_; }

  /// Resets every env (episode counters continue from `episode_base`, e.g. after a resume).
  void ResetAll(uint64_t episode_base = 0);
  /// Replaces the run seed episodes are derived from (takes effect at the next reset).
  void set_seed(uint64_t seed) { seed_ = seed; }
  uint64_t seed() const { return seed_; }
  /// Steps every env with actions [E * act_dim]. Afterwards obs() holds the next observations
  /// (of the new episode where one ended), terminal_obs() the last observation of episodes
  /// that ended (valid where terminated or truncated), and finished() the episodes that ended
  /// in this step, in env order.
  void Step(const float* actions);

  /// Computes a chunk's actions: reads obs rows [begin, end) of `obs` (the observations before
  /// the step) and writes action rows [begin, end) of `actions` ([E * act_dim]).
  using ChunkPolicy = std::function<void(int begin, int end, const float* obs, float* actions)>;
  /// Like Step, but the actions come from `policy`, called on the worker threads for
  /// `chunks` contiguous chunks of envs, each chunk stepped right after its actions are known:
  /// the inference of one chunk overlaps the physics of another, so no core idles while a
  /// single thread runs the policy. `policy` must be safe to call concurrently for distinct
  /// chunks. Same results as Step with the same actions.
  void StepChunked(const ChunkPolicy& policy, int chunks);

  const std::vector<float>& obs() const { return obs_; }
  const std::vector<float>& terminal_obs() const { return terminal_obs_; }
  const std::vector<float>& rewards() const { return rewards_; }
  const std::vector<uint8_t>& terminated() const { return terminated_; }
  const std::vector<uint8_t>& truncated() const { return truncated_; }
  const std::vector<EpisodeStats>& finished() const { return finished_; }
  uint64_t episodes_started() const;

  /// Turns on AMP feature pairs (Unimplemented naming the task when it has none). Call before
  /// ResetAll.
  absl::Status EnableAmp();
  bool amp_enabled() const { return amp_dim_ > 0; }
  int amp_feature_dim() const { return amp_dim_; }
  /// After Step: per env the pair (s_t, s_t+1) of the step, [E x 2F]; s_t+1 is the state the
  /// step reached (before any reset), like terminal_obs().
  const std::vector<float>& amp_pairs() const { return amp_pairs_; }

 private:
  void StepOne(int i, const float* action);  // one env's step, reset and bookkeeping
  void CollectFinished();

  std::unique_ptr<VecTask> task_;
  WorkerPool pool_;
  uint64_t seed_;
  std::vector<float> obs_, terminal_obs_, rewards_;
  std::vector<uint8_t> terminated_, truncated_, ended_;
  std::vector<double> ep_ret_;
  std::vector<int> ep_len_;
  std::vector<uint64_t> ep_count_;
  std::vector<EpisodeStats> ep_done_;  // per env, valid where ended_
  std::vector<EpisodeStats> finished_;
  int amp_dim_ = 0;
  std::vector<float> amp_cur_, amp_pairs_;  // [E x F] current state, [E x 2F] last step
  std::vector<float> chunk_actions_;        // StepChunked's action buffer [E x act_dim]
};

}  // namespace simhuman::learn
