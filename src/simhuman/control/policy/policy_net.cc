#include "simhuman/control/policy/policy_net.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <memory>

namespace simhuman::control {

torch::nn::Sequential MakeMlp(int in, const std::vector<int>& hidden, int out, double out_gain) {
  torch::nn::Sequential seq;
  int prev = in;
  for (int h : hidden) {
    seq->push_back(torch::nn::Linear(prev, h));
    seq->push_back(torch::nn::ELU());
    prev = h;
  }
  torch::nn::Linear last(prev, out);
  {
    torch::NoGradGuard ng;
    last->weight.mul_(out_gain);
    last->bias.zero_();
  }
  seq->push_back(last);
  return seq;
}

GaussianActorImpl::GaussianActorImpl(int obs_dim, int act_dim, const std::vector<int>& hidden,
                                     double init_std) {
  net_ = register_module("net", MakeMlp(obs_dim, hidden, act_dim, 0.01));
  log_std_ =
      register_parameter("log_std", torch::full({act_dim}, std::log(init_std), torch::kFloat32));
}

torch::Tensor GaussianActorImpl::forward(const torch::Tensor& obs) { return net_->forward(obs); }

torch::Tensor GaussianActorImpl::log_std() const {
  return torch::clamp(log_std_, std::log(0.05), 0.0);
}

ObsNormalizer::ObsNormalizer(int dim, double clip) : dim_(dim), clip_(clip) {
  mean_ = torch::zeros({dim}, torch::kFloat64);
  var_ = torch::ones({dim}, torch::kFloat64);
  Cache();
}

void ObsNormalizer::Cache() {
  mean_f_ = mean_.to(torch::kFloat32);
  std_f_ = torch::sqrt(var_ + 1e-8).to(torch::kFloat32);
}

void ObsNormalizer::Update(const torch::Tensor& batch) {
  torch::NoGradGuard ng;
  torch::Tensor x = batch.to(torch::kFloat64).reshape({-1, dim_});
  double n = static_cast<double>(x.size(0));
  if (n <= 0) return;
  Merge(n, x.mean(0), x.var(0, /*unbiased=*/false));
}

void ObsNormalizer::Merge(double n, const torch::Tensor& bm, const torch::Tensor& bv) {
  torch::NoGradGuard ng;
  if (n <= 0) return;
  double total = count_ + n;
  torch::Tensor delta = bm - mean_;
  mean_ = mean_ + delta * (n / total);
  var_ = (var_ * count_ + bv * n + delta * delta * (count_ * n / total)) / total;
  count_ = total;
  Cache();
}

ObsNormalizer ObsNormalizer::Widened(int new_dim) const {
  ObsNormalizer w(std::max(new_dim, dim_), clip_);
  torch::NoGradGuard ng;
  w.mean_.narrow(0, 0, dim_).copy_(mean_);
  w.var_.narrow(0, 0, dim_).copy_(var_);
  w.count_ = count_;
  w.Cache();
  return w;
}

torch::Tensor ObsNormalizer::Normalize(const torch::Tensor& x) const {
  return torch::clamp((x - mean_f_) / std_f_, -clip_, clip_);
}

void ObsNormalizer::Save(torch::serialize::OutputArchive& ar) const {
  ar.write("obs_mean", mean_);
  ar.write("obs_var", var_);
  ar.write("obs_count", c10::IValue(count_));
  ar.write("obs_clip", c10::IValue(clip_));
}

absl::Status ObsNormalizer::Load(torch::serialize::InputArchive& ar, int dim) {
  torch::Tensor m, v;
  c10::IValue c, clip;
  if (!ar.try_read("obs_mean", m) || !ar.try_read("obs_var", v) || !ar.try_read("obs_count", c) ||
      !ar.try_read("obs_clip", clip)) {
    return absl::DataLossError("observation normalizer keys missing");
  }
  if (m.dim() != 1 || m.size(0) != dim || v.sizes() != m.sizes()) {
    return absl::DataLossError("observation normalizer has dimension " + std::to_string(m.numel()) +
                               ", expected " + std::to_string(dim));
  }
  if (!torch::isfinite(m).all().item<bool>() || !torch::isfinite(v).all().item<bool>() ||
      (v < 0).any().item<bool>()) {
    return absl::DataLossError("observation normalizer holds non-finite or negative statistics");
  }
  dim_ = dim;
  mean_ = m.to(torch::kFloat64);
  var_ = v.to(torch::kFloat64);
  count_ = c.toDouble();
  clip_ = clip.toDouble();
  Cache();
  return absl::OkStatus();
}

void SavePolicyKeys(torch::serialize::OutputArchive& ar, const PolicyMeta& meta,
                    GaussianActor& actor, const ObsNormalizer& norm) {
  ar.write("format", c10::IValue(std::string(kPolicyFormat)));
  ar.write("task", c10::IValue(meta.task));
  ar.write("obs_dim", c10::IValue(static_cast<int64_t>(meta.obs_dim)));
  ar.write("act_dim", c10::IValue(static_cast<int64_t>(meta.act_dim)));
  std::vector<int64_t> h(meta.hidden.begin(), meta.hidden.end());
  ar.write("hidden", torch::tensor(h, torch::kInt64));
  if (!meta.variant.empty()) ar.write("variant", c10::IValue(meta.variant));
  if (meta.carry_grip) ar.write("carry_grip", c10::IValue(true));
  torch::serialize::OutputArchive a;
  actor->save(a);
  ar.write("actor", a);
  norm.Save(ar);
}

core::StatusOr<PolicyMeta> ReadPolicyMeta(torch::serialize::InputArchive& ar) {
  c10::IValue format, task, obs_dim, act_dim;
  torch::Tensor hidden;
  if (!ar.try_read("format", format) || !format.isString() ||
      format.toStringRef() != kPolicyFormat) {
    return absl::DataLossError(std::string("not a simhuman policy archive (no format '") +
                               kPolicyFormat + "')");
  }
  if (!ar.try_read("task", task) || !ar.try_read("obs_dim", obs_dim) ||
      !ar.try_read("act_dim", act_dim) || !ar.try_read("hidden", hidden)) {
    return absl::DataLossError("policy metadata keys missing (task, obs_dim, act_dim, hidden)");
  }
  PolicyMeta meta;
  meta.task = task.toStringRef();
  meta.obs_dim = static_cast<int>(obs_dim.toInt());
  meta.act_dim = static_cast<int>(act_dim.toInt());
  hidden = hidden.to(torch::kInt64).contiguous();
  for (int64_t i = 0; i < hidden.numel(); ++i) {
    meta.hidden.push_back(static_cast<int>(hidden.data_ptr<int64_t>()[i]));
  }
  c10::IValue variant;
  if (ar.try_read("variant", variant) && variant.isString()) meta.variant = variant.toStringRef();
  c10::IValue grip;
  meta.carry_grip = ar.try_read("carry_grip", grip) && grip.isBool() && grip.toBool();
  if (meta.obs_dim <= 0 || meta.act_dim <= 0 || meta.hidden.empty()) {
    return absl::DataLossError("policy metadata has invalid dimensions");
  }
  return meta;
}

core::StatusOr<LoadedPolicy> LoadPolicyFile(const std::string& path) {
  if (!std::ifstream(path).good()) return absl::NotFoundError(path + ": cannot open policy file");
  try {
    torch::serialize::InputArchive ar;
    ar.load_from(path);
    auto meta = ReadPolicyMeta(ar);
    if (!meta.ok()) return core::Annotate(meta.status(), path);
    LoadedPolicy p;
    p.meta = *meta;
    p.actor = GaussianActor(meta->obs_dim, meta->act_dim, meta->hidden, 0.5);
    torch::serialize::InputArchive a;
    if (!ar.try_read("actor", a)) return absl::DataLossError(path + ": no 'actor' in the file");
    p.actor->load(a);
    p.actor->eval();
    SH_RETURN_IF_ERROR(core::Annotate(p.norm.Load(ar, meta->obs_dim), path));
    return p;
  } catch (const c10::Error& e) {
    return absl::DataLossError(
        path + ": corrupt or unreadable policy file: " + std::string(e.what_without_backtrace()));
  } catch (const std::exception& e) {
    return absl::DataLossError(path + ": corrupt or unreadable policy file: " + e.what());
  }
}

absl::Status CheckPolicyKind(const LoadedPolicy& loaded, const std::string& path,
                             const std::string& stage, const std::vector<std::string>& tasks,
                             int obs_dim, int act_dim, const std::string& use_instead) {
  const PolicyMeta& meta = loaded.meta;
  if (std::find(tasks.begin(), tasks.end(), meta.task) != tasks.end() && meta.obs_dim == obs_dim &&
      meta.act_dim == act_dim) {
    return absl::OkStatus();
  }
  std::string kinds;
  for (const std::string& t : tasks) kinds += (kinds.empty() ? "" : " or ") + t;
  return absl::InvalidArgumentError(
      stage + " policy '" + path + "' is a '" + meta.task + "' policy with " +
      std::to_string(meta.obs_dim) + " observations and " + std::to_string(meta.act_dim) +
      " actions; a " + kinds + " policy has " + std::to_string(obs_dim) + " and " +
      std::to_string(act_dim) + " (train one with: simhuman train --task " + tasks.back() +
      "), or use '" + use_instead + "'");
}

std::function<void(const float* obs, float* act)> MeanActionFn(LoadedPolicy loaded) {
  auto policy = std::make_shared<LoadedPolicy>(std::move(loaded));
  return [policy](const float* obs, float* act) {
    const int n = policy->meta.obs_dim, k = policy->meta.act_dim;
    std::fill(act, act + k, 0.0f);
    for (int i = 0; i < n; ++i) {
      if (!std::isfinite(obs[i])) return;
    }
    try {
      torch::NoGradGuard ng;
      torch::Tensor x = torch::from_blob(const_cast<float*>(obs), {1, n}, torch::kFloat32);
      torch::Tensor a = policy->actor->forward(policy->norm.Normalize(x)).contiguous();
      std::copy(a.data_ptr<float>(), a.data_ptr<float>() + k, act);
    } catch (const c10::Error&) {
      std::fill(act, act + k, 0.0f);
    }
  };
}

}  // namespace simhuman::control
