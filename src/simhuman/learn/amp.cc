#include "simhuman/learn/amp.h"

#include <cmath>

#include "simhuman/control/policy/policy_net.h"
#include "simhuman/core/check.h"

namespace simhuman::learn {
namespace {

constexpr double kStdFloor = 0.05;
constexpr double kNormClip = 10.0;

}  // namespace

AmpDiscriminatorImpl::AmpDiscriminatorImpl(int feature_dim, const std::vector<int>& hidden)
    : feature_dim_(feature_dim) {
  net_ = register_module("net", control::MakeMlp(2 * feature_dim, hidden, 1, 1.0));
  mean_ = register_buffer("feat_mean", torch::zeros({feature_dim}));
  std_ = register_buffer("feat_std", torch::ones({feature_dim}));
}

void AmpDiscriminatorImpl::FitNormalizer(const torch::Tensor& expert_features) {
  SH_CHECK(expert_features.dim() == 2 && expert_features.size(1) == feature_dim_,
           "expert features must be [N, F]");
  torch::NoGradGuard ng;
  mean_.copy_(expert_features.mean(0));
  std_.copy_(torch::clamp_min(expert_features.std(0, /*unbiased=*/false), kStdFloor));
}

torch::Tensor AmpDiscriminatorImpl::Normalize(const torch::Tensor& pairs) const {
  torch::Tensor m = torch::cat({mean_, mean_}), s = torch::cat({std_, std_});
  return torch::clamp((pairs - m) / s, -kNormClip, kNormClip);
}

torch::Tensor AmpDiscriminatorImpl::forward(const torch::Tensor& normalized_pairs) {
  return net_->forward(normalized_pairs).squeeze(-1);
}

torch::Tensor AmpStyleReward(AmpDiscriminator& disc, const torch::Tensor& pairs,
                             torch::Tensor* d_out) {
  torch::NoGradGuard ng;
  torch::Tensor d = disc->forward(disc->Normalize(pairs));
  if (d_out) *d_out = d;
  return torch::clamp_min(1.0 - 0.25 * (d - 1.0).pow(2), 0.0);
}

torch::Tensor AmpExpertPairs(const std::vector<std::vector<float>>& clip_features,
                             int feature_dim) {
  std::vector<torch::Tensor> parts;
  for (const std::vector<float>& f : clip_features) {
    int64_t n = static_cast<int64_t>(f.size()) / feature_dim;
    if (n < 2) continue;
    torch::Tensor t =
        torch::from_blob(const_cast<float*>(f.data()), {n, feature_dim}, torch::kFloat32).clone();
    parts.push_back(torch::cat({t.slice(0, 0, n - 1), t.slice(0, 1, n)}, 1));
  }
  if (parts.empty()) return torch::empty({0, 2 * feature_dim});
  return torch::cat(parts, 0);
}

AmpReplayBuffer::AmpReplayBuffer(int64_t capacity, int pair_dim)
    : data_(torch::zeros({capacity, pair_dim})) {}

void AmpReplayBuffer::Add(const torch::Tensor& pairs) {
  const int64_t cap = data_.size(0);
  int64_t n = pairs.size(0);
  torch::Tensor src = pairs;
  if (n > cap) {
    src = pairs.slice(0, n - cap, n);
    n = cap;
  }
  int64_t first = std::min(n, cap - next_);
  data_.slice(0, next_, next_ + first).copy_(src.slice(0, 0, first));
  if (first < n) data_.slice(0, 0, n - first).copy_(src.slice(0, first, n));
  next_ = (next_ + n) % cap;
  size_ = std::min(cap, size_ + n);
}

torch::Tensor SampleRows(const torch::Tensor& data, int64_t n, core::Rng& rng) {
  SH_CHECK(data.size(0) > 0, "cannot sample from an empty set");
  std::vector<int64_t> idx(n);
  const int hi = static_cast<int>(data.size(0) - 1);
  for (int64_t& i : idx) i = rng.UniformInt(0, hi);
  return data.index_select(0, torch::tensor(idx, torch::kInt64));
}

torch::Tensor AmpReplayBuffer::Sample(int64_t n, core::Rng& rng) const {
  return SampleRows(data_.slice(0, 0, size_), n, rng);
}

bool AmpUpdate(AmpDiscriminator& disc, torch::optim::Optimizer& opt, const torch::Tensor& expert,
               const torch::Tensor& agent, double grad_penalty, double max_grad_norm,
               AmpUpdateStats* stats) {
  disc->train();
  torch::Tensor xe = disc->Normalize(expert).detach().requires_grad_(true);
  torch::Tensor xa = disc->Normalize(agent).detach();
  torch::Tensor de = disc->forward(xe), da = disc->forward(xa);
  torch::Tensor ls = 0.5 * ((de - 1).pow(2).mean() + (da + 1).pow(2).mean());
  torch::Tensor grad = torch::autograd::grad({de.sum()}, {xe}, {}, /*retain_graph=*/true,
                                             /*create_graph=*/true)[0];
  torch::Tensor gp = grad.pow(2).sum(-1).mean();
  torch::Tensor loss = ls + 0.5 * grad_penalty * gp;
  if (!torch::isfinite(loss).item<bool>()) return false;
  opt.zero_grad();
  loss.backward();
  double gn = torch::nn::utils::clip_grad_norm_(disc->parameters(), max_grad_norm);
  if (!std::isfinite(gn)) {
    opt.zero_grad();
    return false;
  }
  opt.step();
  if (stats) {
    torch::NoGradGuard ng;
    stats->loss = loss.item<double>();
    stats->grad_penalty = gp.item<double>();
    stats->expert_acc = (de > 0).to(torch::kFloat32).mean().item<double>();
    stats->agent_acc = (da < 0).to(torch::kFloat32).mean().item<double>();
    stats->d_expert = de.mean().item<double>();
    stats->d_agent = da.mean().item<double>();
  }
  return true;
}

}  // namespace simhuman::learn
