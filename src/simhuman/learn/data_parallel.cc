#include "simhuman/learn/data_parallel.h"

#include <cstring>

#include "simhuman/core/check.h"

namespace simhuman::learn {

bool AverageGradients(const std::vector<torch::Tensor>& params, core::Communicator& comm,
                      bool local_bad) {
  if (comm.size() == 1) return !local_bad;
  torch::NoGradGuard ng;
  int64_t total = 0;
  for (const torch::Tensor& p : params) total += p.numel();
  // one buffer: every gradient, then this rank's "unusable" flag
  std::vector<float> buf(static_cast<size_t>(total) + 1, 0.f);
  int64_t at = 0;
  for (const torch::Tensor& p : params) {
    if (p.grad().defined()) {
      torch::Tensor g = p.grad().contiguous().to(torch::kFloat32).view({-1});
      std::memcpy(buf.data() + at, g.data_ptr<float>(), sizeof(float) * g.numel());
    }
    at += p.numel();
  }
  buf[total] = local_bad ? 1.f : 0.f;
  absl::Status st = comm.AllreduceSum(buf.data(), static_cast<int64_t>(buf.size()));
  SH_CHECK(st.ok(), std::string(st.message()).c_str());
  if (buf[total] > 0) return false;
  const float scale = 1.f / static_cast<float>(comm.size());
  at = 0;
  for (const torch::Tensor& p : params) {
    torch::Tensor mean =
        torch::from_blob(buf.data() + at, p.sizes(), torch::kFloat32).mul(scale).to(p.dtype());
    if (p.grad().defined()) {
      p.mutable_grad().copy_(mean);
    } else {
      p.mutable_grad() = mean.clone();
    }
    at += p.numel();
  }
  return true;
}

absl::Status MergeNormalizer(const control::ObsNormalizer& before, control::ObsNormalizer* norm,
                             core::Communicator& comm) {
  if (comm.size() == 1) return absl::OkStatus();
  torch::NoGradGuard ng;
  const int d = norm->dim();
  const double n0 = before.count(), nr = norm->count(), nb = nr - n0;
  const torch::Tensor m0 = before.mean(), mr = norm->mean();
  // this rank's rollout alone: count, sum, and squared deviations from its mean
  torch::Tensor sum_b = mr * nr - m0 * n0;
  torch::Tensor mean_b = nb > 0 ? sum_b / nb : torch::zeros({d}, torch::kFloat64);
  torch::Tensor m2_b = norm->var() * nr - before.var() * n0;
  if (nb > 0) m2_b = m2_b - (mean_b - m0).pow(2) * (n0 * nb / nr);
  // the rollouts of all ranks: their count and mean, then their squared deviations
  std::vector<double> first(1 + d);
  first[0] = nb;
  std::memcpy(first.data() + 1, sum_b.contiguous().data_ptr<double>(), sizeof(double) * d);
  SH_RETURN_IF_ERROR(comm.AllreduceSum(first.data(), static_cast<int64_t>(first.size())));
  const double n_all = first[0];
  if (n_all <= 0) {
    *norm = before;
    return absl::OkStatus();
  }
  torch::Tensor mean_all = torch::from_blob(first.data() + 1, {d}, torch::kFloat64).clone() / n_all;
  torch::Tensor m2 = (m2_b + (mean_b - mean_all).pow(2) * nb).clamp_min(0).contiguous();
  std::vector<double> second(m2.data_ptr<double>(), m2.data_ptr<double>() + d);
  SH_RETURN_IF_ERROR(comm.AllreduceSum(second.data(), d));
  torch::Tensor var_all = torch::from_blob(second.data(), {d}, torch::kFloat64).clone() / n_all;
  *norm = before;
  norm->Merge(n_all, mean_all, var_all);
  return absl::OkStatus();
}

absl::Status SumCounts(std::vector<double>* counts, core::Communicator& comm) {
  if (comm.size() == 1) return absl::OkStatus();
  return comm.AllreduceSum(counts->data(), static_cast<int64_t>(counts->size()));
}

}  // namespace simhuman::learn
