#pragma once
/// Advantages of a rollout: generalized advantage estimation (GAE, Schulman et al. 2016) with
/// time-limit bootstrapping. Shared by PpoTrainer and MappoTrainer.
///
/// Includes torch: include it only from learn/*.cc and learn tests. Pure functions.

#include <torch/torch.h>

#include <cstdint>
#include <vector>

namespace simhuman::learn {

/// Adds gamma * V(terminal observation) to the step rewards `rewards` [B] at the rows in
/// `truncated_rows` (episodes ended by the time limit, not by failure), in place.
/// `terminal_values` holds one value per listed row, in the same order.
void AddTimeLimitBootstrap(torch::Tensor& rewards, const std::vector<int64_t>& truncated_rows,
                           const torch::Tensor& terminal_values, float gamma);

/// GAE(gamma, lambda) advantages [T, B] of a rollout of T steps over B rows: `rewards`,
/// `values` and `dones` are [T, B] (dones 1 where the episode ended at that step, terminated or
/// truncated; rewards already hold any time-limit bootstrap), `last_values` [B] the values of
/// the observations after the last step. The returns (value targets) are advantages + values.
torch::Tensor ComputeGae(const torch::Tensor& rewards, const torch::Tensor& values,
                         const torch::Tensor& dones, const torch::Tensor& last_values, float gamma,
                         float lambda);

}  // namespace simhuman::learn
