#pragma once
/// Multi-agent (team) environments for centralised training with decentralised execution
/// (MAPPO; CooHOI's humanoids carrying a box together): E copies of a task with N agents each,
/// stepped by a pool of worker threads with automatic resets. Torch-free (float buffers).
///
/// Every agent of a task has an observation and an action of the same sizes (one actor is
/// shared by the agents) and its own reward; episodes end per env (the team ends together);
/// each env also exposes a shared state, the input of a centralised critic, that execution
/// never sees. Buffers are env-major: agent a of env i is row i * N + a.
///
/// Determinism: env i's episode k is seeded with core::DeriveSeed(seed, i, k), as in VecEnv,
/// so trajectories do not depend on the number of threads or their scheduling.

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "simhuman/learn/vec_env.h"

namespace simhuman::learn {

/// What one team env step reports besides the per-agent rewards.
struct TeamStepInfo {
  bool terminated = false;  ///< ended by failure (no bootstrap)
  bool truncated = false;   ///< ended by the time limit (bootstrap with V(terminal state))
  bool success = false;     ///< the team's success criterion has been met in this episode
};

/// One team task with E independent copies. Reset/Step for distinct env indices may run
/// concurrently; calls for the same index never do.
class MultiAgentVecTask {
 public:
  virtual ~MultiAgentVecTask() = default;
  virtual std::string name() const = 0;
  virtual int num_envs() const = 0;
  virtual int num_agents() const = 0;  ///< N agents per env
  virtual int obs_dim() const = 0;     ///< floats per agent observation
  virtual int act_dim() const = 0;     ///< floats per agent action
  virtual int state_dim() const = 0;   ///< floats of an env's shared state
  /// Starts a new episode of env i from `seed`: writes the agents' first observations
  /// `obs` [N x obs_dim] and the shared state `state` [state_dim].
  virtual void Reset(int i, uint64_t seed, float* obs, float* state) = 0;
  /// Applies `actions` [N x act_dim] (raw floats) to env i; writes the next observations and
  /// state (before any reset), each agent's reward `rewards` [N] and the step's outcome.
  virtual void Step(int i, const float* actions, float* obs, float* state, float* rewards,
                    TeamStepInfo* info) = 0;
  /// Whether agents use action entry j (see VecTask::action_used). Default: all used.
  virtual bool action_used(int j) const { return j >= 0 && j < act_dim(); }
};

/// A finished team episode.
struct TeamEpisodeStats {
  /// ret: the mean over agents of their returns; success and terminated: the team's.
  EpisodeStats team;
  std::vector<double> agent_returns;  ///< [N] each agent's return
};

/// Batched stepping of a MultiAgentVecTask with automatic resets.
class MultiAgentVecEnv {
 public:
  MultiAgentVecEnv(std::unique_ptr<MultiAgentVecTask> task, int threads, uint64_t seed);
  int num_envs() const { return task_->num_envs(); }
  int num_agents() const { return task_->num_agents(); }
  int obs_dim() const { return task_->obs_dim(); }
  int act_dim() const { return task_->act_dim(); }
  int state_dim() const { return task_->state_dim(); }
  MultiAgentVecTask& task() { return *task_; }

  /// Resets every env (episode counters continue from `episode_base`, e.g. after a resume).
  void ResetAll(uint64_t episode_base = 0);
  /// Steps every env with actions [E * N * act_dim]. Afterwards obs() and state() hold the
  /// next observations and states (of the new episode where one ended), terminal_obs() and
  /// terminal_state() the last ones of episodes that ended (valid where terminated or
  /// truncated), rewards() the step's per-agent rewards and finished() the episodes that
  /// ended in this step, in env order.
  void Step(const float* actions);

  const std::vector<float>& obs() const { return obs_; }      ///< [E*N x obs_dim]
  const std::vector<float>& state() const { return state_; }  ///< [E x state_dim]
  const std::vector<float>& terminal_obs() const { return terminal_obs_; }
  const std::vector<float>& terminal_state() const { return terminal_state_; }
  const std::vector<float>& rewards() const { return rewards_; }          ///< [E*N]
  const std::vector<uint8_t>& terminated() const { return terminated_; }  ///< [E]
  const std::vector<uint8_t>& truncated() const { return truncated_; }    ///< [E]
  const std::vector<TeamEpisodeStats>& finished() const { return finished_; }

 private:
  void StepOne(int i, const float* actions);  // one env's step, reset and bookkeeping
  void ResetOne(int i);

  std::unique_ptr<MultiAgentVecTask> task_;
  WorkerPool pool_;
  uint64_t seed_;
  std::vector<float> obs_, state_, terminal_obs_, terminal_state_, rewards_;
  std::vector<uint8_t> terminated_, truncated_, ended_;
  std::vector<double> ep_ret_;  // [E*N]
  std::vector<int> ep_len_;
  std::vector<uint64_t> ep_count_;
  std::vector<TeamEpisodeStats> ep_done_;  // per env, valid where ended_
  std::vector<TeamEpisodeStats> finished_;
};

}  // namespace simhuman::learn
