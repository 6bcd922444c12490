#include "simhuman/learn/ppo_update.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <random>
#include <string>

#include "simhuman/core/check.h"
#include "simhuman/learn/data_parallel.h"

namespace simhuman::learn {
namespace {

constexpr double kLog2Pi = 1.8378770664093453;

// whether the epochs stop on this minibatch's KL; data-parallel ranks decide on the mean KL
// so that they run the same number of allreduces
bool KlTooLarge(double mb_kl, double target_kl, core::Communicator* comm) {
  if (comm && comm->size() > 1) {
    std::vector<double> v{mb_kl};
    absl::Status sum = SumCounts(&v, *comm);
    SH_CHECK(sum.ok(), std::string(sum.message()).c_str());
    mb_kl = v[0] / comm->size();
  }
  return mb_kl > 1.5 * target_kl;
}

}  // namespace

std::vector<torch::Tensor> ActorCritic::Params() const {
  std::vector<torch::Tensor> p = actor->parameters();
  for (auto& t : critic->parameters()) p.push_back(t);
  return p;
}

double ActorCritic::ActionStd() const {
  torch::NoGradGuard ng;
  return ((torch::exp(actor->log_std()) * act_used).sum() / act_used.sum()).item<double>();
}

ActorCritic MakeActorCritic(int obs_dim, int critic_dim, int act_dim,
                            const std::vector<int>& hidden, const std::vector<int>& critic_hidden,
                            double init_std, double lr, const std::vector<float>& used) {
  ActorCritic net;
  net.actor = control::GaussianActor(obs_dim, act_dim, hidden, init_std);
  net.critic = control::MakeMlp(critic_dim, critic_hidden.empty() ? hidden : critic_hidden, 1, 1.0);
  net.act_used = torch::tensor(used);
  net.opt = std::make_unique<torch::optim::Adam>(net.Params(), torch::optim::AdamOptions(lr));
  return net;
}

void SetLearningRate(torch::optim::Adam& opt, double lr) {
  for (auto& g : opt.param_groups()) {
    static_cast<torch::optim::AdamOptions&>(g.options()).lr(lr);
  }
}

torch::Tensor GaussianLogProb(const torch::Tensor& a, const torch::Tensor& mean,
                              const torch::Tensor& log_std, const torch::Tensor& used) {
  torch::Tensor z = (a - mean) * torch::exp(-log_std);
  return ((-0.5 * z * z - log_std - 0.5 * kLog2Pi) * used).sum(-1);
}

torch::Tensor DrawGaussian(core::Rng& rng, int64_t rows, int64_t cols) {
  torch::Tensor t = torch::empty({rows, cols}, torch::kFloat32);
  float* p = t.data_ptr<float>();
  std::normal_distribution<float> nd(0.f, 1.f);
  for (int64_t i = 0; i < rows * cols; ++i) p[i] = nd(rng.engine());
  return t;
}

PpoUpdateStats PpoUpdate(ActorCritic& net, const PpoBatch& batch, const PpoUpdateOptions& options,
                         core::Rng& rng) {
  PpoUpdateStats st;
  const torch::Tensor& obs = batch.obs;
  const torch::Tensor& critic_obs = batch.critic_obs.defined() ? batch.critic_obs : batch.obs;
  const int64_t n = obs.size(0);
  torch::Tensor adv = (batch.adv - batch.adv.mean()) / (batch.adv.std() + 1e-8);
  st.rollout_finite =
      torch::isfinite(obs).all().item<bool>() &&
      (!batch.critic_obs.defined() || torch::isfinite(critic_obs).all().item<bool>()) &&
      torch::isfinite(batch.ret).all().item<bool>() && torch::isfinite(adv).all().item<bool>();
  if (options.comm && options.comm->size() > 1) {
    // one rank's non-finite rollout stops the update on every rank (they step together)
    std::vector<double> bad{st.rollout_finite ? 0.0 : 1.0};
    absl::Status sum = SumCounts(&bad, *options.comm);
    SH_CHECK(sum.ok(), std::string(sum.message()).c_str());
    st.rollout_finite = bad[0] == 0;
  }
  if (!st.rollout_finite) {
    st.skipped = options.epochs * options.minibatches;
    return st;
  }
  const std::vector<torch::Tensor> params = net.Params();
  const torch::Tensor& used = net.act_used;
  const double clip = options.clip;
  net.actor->train();
  double pl = 0, vl = 0, ent = 0, kl = 0, cf = 0;
  const int64_t mb = n / options.minibatches;
  std::vector<int64_t> perm(n);
  for (int ep = 0; ep < options.epochs; ++ep) {
    std::iota(perm.begin(), perm.end(), 0);
    std::shuffle(perm.begin(), perm.end(), rng.engine());
    torch::Tensor perm_t = torch::tensor(perm, torch::kInt64);
    for (int k = 0; k < options.minibatches; ++k) {
      torch::Tensor idx = perm_t.slice(0, k * mb, (k + 1) * mb);
      torch::Tensor o = obs.index_select(0, idx), a = batch.act.index_select(0, idx);
      torch::Tensor co = batch.critic_obs.defined() ? critic_obs.index_select(0, idx) : o;
      torch::Tensor olp = batch.old_logp.index_select(0, idx);
      torch::Tensor ov = batch.old_value.index_select(0, idx);
      torch::Tensor r = batch.ret.index_select(0, idx), ad = adv.index_select(0, idx);
      torch::Tensor mean = net.actor->forward(o);
      torch::Tensor log_std = net.actor->log_std();
      torch::Tensor logp = GaussianLogProb(a, mean, log_std, used);
      torch::Tensor ratio = torch::exp(logp - olp);
      torch::Tensor pg =
          -torch::min(ratio * ad, torch::clamp(ratio, 1 - clip, 1 + clip) * ad).mean();
      torch::Tensor v = net.critic->forward(co).squeeze(-1);
      torch::Tensor vc = ov + torch::clamp(v - ov, -options.value_clip, options.value_clip);
      torch::Tensor vloss = 0.5 * torch::max((v - r).pow(2), (vc - r).pow(2)).mean();
      torch::Tensor entropy = ((log_std + 0.5 + 0.5 * kLog2Pi) * used).sum();
      torch::Tensor loss = options.critic_only
                               ? options.value_coef * vloss
                               : pg + options.value_coef * vloss - options.entropy_coef * entropy;
      const bool loss_finite = torch::isfinite(loss).item<bool>();
      net.opt->zero_grad();
      if (loss_finite) loss.backward();
      // data-parallel: the mean gradient over the ranks (all skip if one rank's loss is bad)
      const bool usable =
          options.comm ? AverageGradients(params, *options.comm, !loss_finite) : loss_finite;
      if (!usable) {
        ++st.skipped;
        net.opt->zero_grad();
        continue;
      }
      double gn = torch::nn::utils::clip_grad_norm_(params, options.max_grad_norm);
      if (!std::isfinite(gn)) {
        ++st.skipped;
        net.opt->zero_grad();
        continue;
      }
      net.opt->step();
      torch::NoGradGuard ng;
      pl += pg.item<double>();
      vl += vloss.item<double>();
      ent += entropy.item<double>();
      torch::Tensor log_ratio = logp.detach() - olp;
      const double mb_kl = ((torch::exp(log_ratio) - 1) - log_ratio).mean().item<double>();
      kl += mb_kl;
      cf += (torch::abs(ratio.detach() - 1) > clip).to(torch::kFloat32).mean().item<double>();
      ++st.minibatches;
      if (options.target_kl > 0 && !options.critic_only &&
          KlTooLarge(mb_kl, options.target_kl, options.comm)) {
        st.kl_stopped = true;
        break;
      }
    }
    if (st.kl_stopped) break;
  }
  if (st.minibatches > 0) {
    st.policy_loss = pl / st.minibatches;
    st.value_loss = vl / st.minibatches;
    st.entropy = ent / st.minibatches;
    st.approx_kl = kl / st.minibatches;
    st.clip_frac = cf / st.minibatches;
  }
  return st;
}

void NonFiniteGuard::Begin(const std::vector<torch::Tensor>& params) {
  params_ = params;
  backup_.clear();
  for (const auto& p : params_) backup_.push_back(p.detach().clone());
}

absl::Status NonFiniteGuard::End(const PpoUpdateStats& stats, int64_t iteration) {
  bool params_finite = true;
  for (const auto& p : params_) {
    params_finite = params_finite && torch::isfinite(p).all().item<bool>();
  }
  if (!params_finite) {
    torch::NoGradGuard ng;
    for (size_t i = 0; i < params_.size(); ++i) params_[i].copy_(backup_[i]);
  }
  backup_.clear();
  if (stats.rollout_finite && params_finite && stats.skipped == 0) {
    bad_in_row_ = 0;
    return absl::OkStatus();
  }
  if (++bad_in_row_ >= max_bad_in_row_) {
    return absl::InternalError("training aborted: " + std::to_string(bad_in_row_) +
                               " non-finite updates in a row at iteration " +
                               std::to_string(iteration));
  }
  return absl::OkStatus();
}

}  // namespace simhuman::learn
