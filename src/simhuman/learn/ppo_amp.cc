#include "simhuman/learn/ppo_amp.h"

#include <vector>

#include "simhuman/learn/bvh.h"
#include "simhuman/learn/ppo.h"
#include "simhuman/learn/vec_env.h"

namespace simhuman::learn {

core::StatusOr<std::unique_ptr<AmpStage>> AmpStage::Create(const PpoConfig& config, VecEnv& env) {
  if (config.amp_clips.empty()) return std::unique_ptr<AmpStage>();
  absl::Status on = env.EnableAmp();
  if (!on.ok()) return absl::InvalidArgumentError("amp_clips: " + std::string(on.message()));
  const int f = env.task().amp_feature_dim();
  std::vector<std::vector<float>> feats;
  for (const std::string& path : config.amp_clips) {
    SH_ASSIGN_OR_RETURN(MotionClip clip, LoadAnyClip(path));
    SH_ASSIGN_OR_RETURN(std::vector<float> ft, env.task().AmpClipFeatures(clip));
    if (ft.size() < 2 * static_cast<size_t>(f)) {
      return absl::InvalidArgumentError(path +
                                        ": the clip is too short for AMP (it needs "
                                        "two frames at the policy rate)");
    }
    feats.push_back(std::move(ft));
  }
  std::unique_ptr<AmpStage> amp(new AmpStage());
  amp->cfg_ = config;
  amp->feature_dim_ = f;
  amp->expert_ = AmpExpertPairs(feats, f);
  amp->disc_ = AmpDiscriminator(f, config.amp_disc_hidden);
  amp->disc_->FitNormalizer(amp->expert_.slice(1, 0, f));
  amp->opt_ = std::make_unique<torch::optim::Adam>(amp->disc_->parameters(),
                                                   torch::optim::AdamOptions(config.amp_disc_lr));
  amp->replay_ = std::make_unique<AmpReplayBuffer>(config.amp_replay_size, 2 * f);
  return amp;
}

void AmpStage::BeginRollout(int steps, int envs) {
  pairs_ = torch::empty({steps, envs, 2 * feature_dim_});
  style_sum_ = task_sum_ = 0;
}

torch::Tensor AmpStage::MixReward(int t, const torch::Tensor& task_reward, const float* pairs) {
  const int64_t envs = task_reward.size(0);
  torch::Tensor p = torch::from_blob(const_cast<float*>(pairs), {envs, 2 * feature_dim_}).clone();
  torch::Tensor style = AmpStyleReward(disc_, p);
  pairs_[t] = p;
  style_sum_ += style.sum().item<double>();
  task_sum_ += task_reward.sum().item<double>();
  return static_cast<float>(cfg_.amp_task_weight) * task_reward +
         static_cast<float>(cfg_.amp_style_weight) * style;
}

void AmpStage::Update(core::Rng& rng, IterationStats* st) {
  const int64_t n = pairs_.size(0) * pairs_.size(1);
  replay_->Add(pairs_.reshape({n, 2 * feature_dim_}));
  AmpUpdateStats sum;
  int n_ok = 0;
  for (int k = 0; k < cfg_.amp_disc_updates; ++k) {
    torch::Tensor e = SampleRows(expert_, cfg_.amp_disc_batch, rng);
    torch::Tensor a = replay_->Sample(cfg_.amp_disc_batch, rng);
    AmpUpdateStats s1;
    if (!AmpUpdate(disc_, *opt_, e, a, cfg_.amp_grad_penalty, cfg_.max_grad_norm, &s1)) {
      ++st->amp_skipped;
      continue;
    }
    sum.loss += s1.loss;
    sum.grad_penalty += s1.grad_penalty;
    sum.expert_acc += s1.expert_acc;
    sum.agent_acc += s1.agent_acc;
    sum.d_expert += s1.d_expert;
    sum.d_agent += s1.d_agent;
    ++n_ok;
  }
  st->amp = true;
  if (n_ok > 0) {
    st->amp_disc_loss = sum.loss / n_ok;
    st->amp_grad_penalty = sum.grad_penalty / n_ok;
    st->amp_expert_acc = sum.expert_acc / n_ok;
    st->amp_agent_acc = sum.agent_acc / n_ok;
    st->amp_d_expert = sum.d_expert / n_ok;
    st->amp_d_agent = sum.d_agent / n_ok;
  }
  st->amp_style_reward = style_sum_ / static_cast<double>(n);
  st->amp_task_reward = task_sum_ / static_cast<double>(n);
}

void AmpStage::Save(torch::serialize::OutputArchive& ar) {
  torch::serialize::OutputArchive d, dopt;
  disc_->save(d);
  ar.write("amp_disc", d);
  opt_->save(dopt);
  ar.write("amp_optim", dopt);
}

absl::Status AmpStage::Load(torch::serialize::InputArchive& ar, const std::string& path) {
  torch::serialize::InputArchive d, dopt;
  if (!ar.try_read("amp_disc", d) || !ar.try_read("amp_optim", dopt)) {
    return absl::DataLossError(path +
                               ": the config has amp_clips but the checkpoint holds no "
                               "discriminator (amp_disc, amp_optim)");
  }
  disc_->load(d);
  opt_->load(dopt);
  return absl::OkStatus();
}

}  // namespace simhuman::learn
