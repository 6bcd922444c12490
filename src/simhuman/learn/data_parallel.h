#pragma once
/// Synchronous data-parallel PPO over the ranks of a core::Communicator (DD-PPO style): every
/// rank collects its own rollout with its own environments, the gradients of each minibatch
/// are averaged over the ranks with one allreduce before clipping and the Adam step (so the
/// weights stay identical on every rank), and the observation normaliser's statistics of the
/// rollout are merged over the ranks after it. The sums run in an order fixed by the number
/// of ranks, so the same seed and rank count give the same weights.
///
/// Includes torch: include it only from learn/*.cc and learn tests.

#include <torch/torch.h>

#include <vector>

#include "simhuman/control/policy/policy_net.h"
#include "simhuman/core/communicator.h"

namespace simhuman::learn {

/// Collective: replaces the gradients of `params` (undefined ones count as zero) by their mean
/// over the ranks. `local_bad` marks this rank's minibatch as unusable (a non-finite loss or
/// gradient); returns false, on every rank, when any rank's was, and then the caller skips
/// the step. With one rank: returns !local_bad and leaves the gradients alone. An MPI failure
/// aborts (SH_CHECK): the ranks could no longer agree on the weights.
bool AverageGradients(const std::vector<torch::Tensor>& params, core::Communicator& comm,
                      bool local_bad);

/// Collective: `norm` was `before` (the same on every rank) plus this rank's rollout; on
/// return it is `before` plus every rank's rollout. Errors: the communicator's.
absl::Status MergeNormalizer(const control::ObsNormalizer& before, control::ObsNormalizer* norm,
                             core::Communicator& comm);

/// Collective: element-wise sums over the ranks of small counters (episodes, successes).
absl::Status SumCounts(std::vector<double>* counts, core::Communicator& comm);

}  // namespace simhuman::learn
