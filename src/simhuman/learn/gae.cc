#include "simhuman/learn/gae.h"

namespace simhuman::learn {

void AddTimeLimitBootstrap(torch::Tensor& rewards, const std::vector<int64_t>& truncated_rows,
                           const torch::Tensor& terminal_values, float gamma) {
  if (truncated_rows.empty()) return;
  torch::Tensor idx = torch::tensor(truncated_rows, torch::kInt64);
  rewards.index_add_(0, idx, gamma * terminal_values);
}

torch::Tensor ComputeGae(const torch::Tensor& rewards, const torch::Tensor& values,
                         const torch::Tensor& dones, const torch::Tensor& last_values, float gamma,
                         float lambda) {
  const int64_t steps = rewards.size(0), rows = rewards.size(1);
  torch::Tensor adv = torch::zeros({steps, rows});
  torch::Tensor gae = torch::zeros({rows});
  for (int64_t t = steps - 1; t >= 0; --t) {
    torch::Tensor next_v = t == steps - 1 ? last_values : values[t + 1];
    torch::Tensor nonterm = 1.f - dones[t];
    torch::Tensor delta = rewards[t] + gamma * next_v * nonterm - values[t];
    gae = delta + gamma * lambda * nonterm * gae;
    adv[t] = gae;
  }
  return adv;
}

}  // namespace simhuman::learn
