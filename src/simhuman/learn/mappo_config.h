#pragma once
/// The multi-agent PPO trainer's configuration (MappoTrainer, learn/mappo.h): one strict
/// struct, read from and written to JSON. The PPO keys mean what they mean in PpoConfig.

#include <cstdint>
#include <nlohmann/json.hpp>
#include <string>
#include <string_view>
#include <vector>

#include "simhuman/core/status.h"

namespace simhuman::learn {

/// MAPPO training configuration (strict JSON: unknown keys are errors, missing keys keep the
/// defaults below).
struct MappoConfig {
  std::string task = "team_carry";  ///< a name of MultiAgentTaskNames()
  int num_agents = 2;               ///< agents per env (the task's team size)
  int64_t total_steps = 2'000'000;  ///< env steps (one step moves the whole team)
  int num_envs = 64;
  int threads = 2;        ///< env worker threads
  int torch_threads = 1;  ///< LibTorch intra-op threads
  uint64_t seed = 1;
  int rollout_steps = 64;  ///< per env per iteration
  int epochs = 5;
  int minibatches = 4;
  double lr = 3e-4;
  double lr_final_frac = 0.3;  ///< lr decays linearly to lr * this at total_steps
  double gamma = 0.99, lambda = 0.95;
  double clip = 0.2;
  double value_clip = 1.0;
  double value_coef = 0.5;
  double entropy_coef = 0.001;
  double max_grad_norm = 1.0;
  double init_std = 0.5;
  std::vector<int> hidden = {64, 64};           ///< shared actor layer widths
  std::vector<int> critic_hidden = {128, 128};  ///< centralised critic widths (empty: hidden)
  /// The critic reads the env's shared state and the agent's one-hot id; with this also the
  /// agent's own observation (MAPPO's agent-specific global state).
  bool critic_agent_obs = true;
  double checkpoint_every_s = 180;
  int max_bad_updates = 5;  ///< abort after this many non-finite updates in a row

  /// Every field in range; the message names the key, its value and the valid range.
  absl::Status Validate() const;
  nlohmann::json ToJson() const;
  /// Strict: unknown keys, wrong types and values out of range are InvalidArgument naming the
  /// JSON pointer (`where` + "/key") and what is valid.
  static core::StatusOr<MappoConfig> FromJson(const nlohmann::json& j, std::string_view where = "");
};

}  // namespace simhuman::learn
