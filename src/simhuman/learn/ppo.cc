#include "simhuman/learn/ppo.h"

#include <omp.h>
#include <torch/torch.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <deque>
#include <filesystem>
#include <fstream>
#include <numeric>
#include <sstream>

#include "simhuman/control/policy/policy_net.h"
#include "simhuman/core/rng.h"
#include "simhuman/learn/amp.h"
#include "simhuman/learn/bvh.h"
#include "simhuman/learn/reach_env.h"
#include "simhuman/learn/vec_env.h"
#include "simhuman/learn/walk_env.h"

namespace simhuman::learn {
namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

namespace {

constexpr char kCheckpointName[] = "checkpoint.pt";
constexpr int kStatsWindow = 200;
constexpr double kLog2Pi = 1.8378770664093453;

core::StatusOr<std::unique_ptr<VecTask>> MakeTask(const std::string& name, int envs,
                                                  const std::string& solver) {
  if (name == "walk") {
    SH_ASSIGN_OR_RETURN(std::unique_ptr<WalkTask> t,
                        WalkTask::Create(envs, solver != "newton" ? WalkPhysicsSolver::kPgs
                                                                  : WalkPhysicsSolver::kNewton));
    return std::unique_ptr<VecTask>(std::move(t));
  }
  if (name == "reach") return std::unique_ptr<VecTask>(new ReachTask(envs));
  return absl::InvalidArgumentError("unknown task '" + name + "'; valid: walk, reach");
}

// sum over the used action dims (`used`: 1 or 0 per dim) of the diagonal Gaussian log density
torch::Tensor LogProb(const torch::Tensor& a, const torch::Tensor& mean,
                      const torch::Tensor& log_std, const torch::Tensor& used) {
  torch::Tensor z = (a - mean) * torch::exp(-log_std);
  return ((-0.5 * z * z - log_std - 0.5 * kLog2Pi) * used).sum(-1);
}

absl::Status SaveAtomic(torch::serialize::OutputArchive& ar, const std::string& path) {
  std::string tmp = path + ".tmp";
  try {
    ar.save_to(tmp);
  } catch (const c10::Error& e) {
    return absl::PermissionDeniedError(tmp + ": cannot write: " + e.what_without_backtrace());
  }
  std::error_code ec;
  fs::rename(tmp, path, ec);
  if (ec) return absl::PermissionDeniedError(path + ": cannot replace: " + ec.message());
  return absl::OkStatus();
}

}  // namespace

nlohmann::json IterationStats::ToJson() const {
  nlohmann::json j{{"iteration", iteration},     {"env_steps", env_steps},
                   {"wall_s", wall_s},           {"return", mean_return},
                   {"ep_length", mean_length},   {"success", success_rate},
                   {"fall", fall_rate},          {"episodes", episodes},
                   {"policy_loss", policy_loss}, {"value_loss", value_loss},
                   {"entropy", entropy},         {"approx_kl", approx_kl},
                   {"clip_frac", clip_frac},     {"lr", lr},
                   {"action_std", action_std},   {"curriculum", curriculum},
                   {"steps_per_s", steps_per_s}, {"collect_s", collect_s},
                   {"update_s", update_s},       {"skipped", skipped_minibatches}};
  if (amp) {
    j["amp_disc_loss"] = amp_disc_loss;
    j["amp_grad_penalty"] = amp_grad_penalty;
    j["amp_expert_acc"] = amp_expert_acc;
    j["amp_agent_acc"] = amp_agent_acc;
    j["amp_d_expert"] = amp_d_expert;
    j["amp_d_agent"] = amp_d_agent;
    j["amp_style_reward"] = amp_style_reward;
    j["amp_task_reward"] = amp_task_reward;
    j["amp_skipped"] = amp_skipped;
  }
  return j;
}

struct PpoTrainer::Impl {
  PpoConfig cfg;
  std::string out;
  std::unique_ptr<VecEnv> env;
  control::GaussianActor actor{nullptr};
  torch::nn::Sequential critic{nullptr};
  torch::Tensor act_used;  // [A] 1 for action dims the task uses, 0 for ignored ones
  std::unique_ptr<torch::optim::Adam> opt;
  control::ObsNormalizer norm;
  core::Rng rng{0};
  int64_t iteration = 0, env_steps = 0, episodes = 0;
  double wall_s = 0;
  double best_success = -1;
  int bad_in_row = 0;
  std::deque<EpisodeStats> window;
  int curr_count = 0, curr_success = 0;  // episodes since the last curriculum check
  int64_t curr_steps = 0;                // env steps at the current level
  Clock::time_point last_ckpt = Clock::now();
  // AMP (null when off)
  struct Amp {
    AmpDiscriminator disc{nullptr};
    std::unique_ptr<torch::optim::Adam> opt;
    torch::Tensor expert;  // [M, 2F] expert pairs
    std::unique_ptr<AmpReplayBuffer> replay;
  };
  std::unique_ptr<Amp> amp;

  // loads the clips and builds the discriminator; call after Build, before ResetAll
  absl::Status BuildAmp() {
    if (cfg.amp_clips.empty()) return absl::OkStatus();
    absl::Status on = env->EnableAmp();
    if (!on.ok()) return absl::InvalidArgumentError("amp_clips: " + std::string(on.message()));
    const int f = env->task().amp_feature_dim();
    std::vector<std::vector<float>> feats;
    for (const std::string& path : cfg.amp_clips) {
      SH_ASSIGN_OR_RETURN(MotionClip clip, LoadAnyClip(path));
      SH_ASSIGN_OR_RETURN(std::vector<float> ft, env->task().AmpClipFeatures(clip));
      if (ft.size() < 2 * static_cast<size_t>(f)) {
        return absl::InvalidArgumentError(path +
                                          ": the clip is too short for AMP (it needs "
                                          "two frames at the policy rate)");
      }
      feats.push_back(std::move(ft));
    }
    amp = std::make_unique<Amp>();
    amp->expert = AmpExpertPairs(feats, f);
    amp->disc = AmpDiscriminator(f, cfg.amp_disc_hidden);
    amp->disc->FitNormalizer(amp->expert.slice(1, 0, f));
    amp->opt = std::make_unique<torch::optim::Adam>(amp->disc->parameters(),
                                                    torch::optim::AdamOptions(cfg.amp_disc_lr));
    amp->replay = std::make_unique<AmpReplayBuffer>(cfg.amp_replay_size, 2 * f);
    return absl::OkStatus();
  }

  // copies the policy of cfg.init_from (if any) into the fresh actor and normalizer
  absl::Status InitFrom() {
    if (cfg.init_from.empty()) return absl::OkStatus();
    const std::string where = "init_from '" + cfg.init_from + "'";
    core::StatusOr<control::LoadedPolicy> p = control::LoadPolicyFile(cfg.init_from);
    if (!p.ok())
      return absl::InvalidArgumentError(where + ": " + std::string(p.status().message()));
    const int d = env->obs_dim(), a = env->act_dim();
    if (p->meta.task != cfg.task || p->meta.obs_dim != d || p->meta.act_dim != a ||
        p->meta.hidden != cfg.hidden) {
      auto dims = [](const std::vector<int>& h) {
        std::string s;
        for (int x : h) s += (s.empty() ? "" : ",") + std::to_string(x);
        return s;
      };
      return absl::InvalidArgumentError(
          where + " holds a '" + p->meta.task + "' policy (obs " + std::to_string(p->meta.obs_dim) +
          ", act " + std::to_string(p->meta.act_dim) + ", hidden " + dims(p->meta.hidden) +
          ") but this run is '" + cfg.task + "' (obs " + std::to_string(d) + ", act " +
          std::to_string(a) + ", hidden " + dims(cfg.hidden) + "); set \"hidden\" to match");
    }
    torch::NoGradGuard no_grad;
    auto src = p->actor->named_parameters();
    for (auto& dst : actor->named_parameters()) {
      const torch::Tensor* s = src.find(dst.key());
      if (!s || s->sizes() != dst.value().sizes()) {
        return absl::InvalidArgumentError(where + ": parameter '" + dst.key() +
                                          "' missing or of "
                                          "another shape");
      }
      dst.value().copy_(*s);
    }
    norm = p->norm;
    return absl::OkStatus();
  }

  std::vector<torch::Tensor> Params() {
    std::vector<torch::Tensor> p = actor->parameters();
    for (auto& t : critic->parameters()) p.push_back(t);
    return p;
  }

  void Build() {
    torch::set_num_threads(cfg.torch_threads);
    torch::manual_seed(cfg.seed);
    int d = env->obs_dim(), a = env->act_dim();
    actor = control::GaussianActor(d, a, cfg.hidden, cfg.init_std);
    critic =
        control::MakeMlp(d, cfg.critic_hidden.empty() ? cfg.hidden : cfg.critic_hidden, 1, 1.0);
    std::vector<float> used(a);
    for (int j = 0; j < a; ++j) used[j] = env->task().action_used(j) ? 1.f : 0.f;
    act_used = torch::tensor(used);
    opt = std::make_unique<torch::optim::Adam>(Params(), torch::optim::AdamOptions(cfg.lr));
    norm = control::ObsNormalizer(d);
    rng = core::Rng(core::DeriveSeed(cfg.seed, 0x5050));
  }

  control::PolicyMeta Meta() const {
    return control::PolicyMeta{cfg.task, env->obs_dim(), env->act_dim(), cfg.hidden};
  }

  double Lr() const {
    double f = std::min(1.0, static_cast<double>(env_steps) / static_cast<double>(cfg.total_steps));
    return cfg.lr * (1.0 - (1.0 - cfg.lr_final_frac) * f);
  }

  torch::Tensor Gaussian(int64_t rows, int64_t cols) {
    torch::Tensor t = torch::empty({rows, cols}, torch::kFloat32);
    float* p = t.data_ptr<float>();
    std::normal_distribution<float> nd(0.f, 1.f);
    for (int64_t i = 0; i < rows * cols; ++i) p[i] = nd(rng.engine());
    return t;
  }

  absl::Status WriteCheckpoint(const std::string& path) {
    try {
      torch::serialize::OutputArchive ar;
      control::SavePolicyKeys(ar, Meta(), actor, norm);
      torch::serialize::OutputArchive c, o;
      critic->save(c);
      ar.write("critic", c);
      opt->save(o);
      ar.write("optim", o);
      std::ostringstream r;
      r << rng.engine();
      ar.write("rng", c10::IValue(r.str()));
      ar.write("iteration", c10::IValue(iteration));
      ar.write("env_steps", c10::IValue(env_steps));
      ar.write("episodes", c10::IValue(episodes));
      ar.write("wall_s", c10::IValue(wall_s));
      ar.write("best_success", c10::IValue(best_success));
      ar.write("curriculum", c10::IValue(env->task().curriculum()));
      ar.write("config", c10::IValue(cfg.ToJson().dump()));
      if (amp) {
        torch::serialize::OutputArchive d, dopt;
        amp->disc->save(d);
        ar.write("amp_disc", d);
        amp->opt->save(dopt);
        ar.write("amp_optim", dopt);
      }
      return SaveAtomic(ar, path);
    } catch (const c10::Error& e) {
      return absl::InternalError(path + ": " + e.what_without_backtrace());
    }
  }

  absl::Status WritePolicy(const std::string& path) {
    torch::serialize::OutputArchive ar;
    control::SavePolicyKeys(ar, Meta(), actor, norm);
    ar.write("env_steps", c10::IValue(env_steps));
    return SaveAtomic(ar, path);
  }

  void AppendLog(const IterationStats& s) {
    std::ofstream f(out + "/log.jsonl", std::ios::app);
    f << s.ToJson().dump() << "\n";
  }
};

PpoTrainer::PpoTrainer(std::unique_ptr<Impl> impl) : impl_(std::move(impl)) {}
PpoTrainer::~PpoTrainer() = default;
bool PpoTrainer::done() const { return impl_->env_steps >= impl_->cfg.total_steps; }
int64_t PpoTrainer::env_steps() const { return impl_->env_steps; }
const PpoConfig& PpoTrainer::config() const { return impl_->cfg; }
const std::string& PpoTrainer::out_dir() const { return impl_->out; }

core::StatusOr<std::unique_ptr<PpoTrainer>> PpoTrainer::Create(const PpoConfig& config,
                                                               const std::string& out_dir) {
  SH_RETURN_IF_ERROR(config.Validate());
  SH_ASSIGN_OR_RETURN(std::unique_ptr<VecTask> task,
                      MakeTask(config.task, config.num_envs, config.physics_solver));
  return CreateWithTask(config, out_dir, std::move(task));
}

core::StatusOr<std::unique_ptr<PpoTrainer>> PpoTrainer::CreateWithTask(
    const PpoConfig& config, const std::string& out_dir, std::unique_ptr<VecTask> task) {
  SH_RETURN_IF_ERROR(config.Validate());
  std::error_code ec;
  if (fs::exists(fs::path(out_dir) / kCheckpointName, ec)) {
    return absl::AlreadyExistsError(out_dir +
                                    " already holds a checkpoint; continue it with "
                                    "--resume or choose another --out");
  }
  auto impl = std::make_unique<Impl>();
  impl->cfg = config;
  impl->out = out_dir;
  impl->env = std::make_unique<VecEnv>(std::move(task), config.threads, config.seed);
  impl->Build();
  SH_RETURN_IF_ERROR(impl->InitFrom());
  SH_RETURN_IF_ERROR(impl->BuildAmp());
  // the run's folder appears only once its inputs (init_from, AMP clips) have loaded
  fs::create_directories(out_dir, ec);
  if (ec) return absl::PermissionDeniedError(out_dir + ": cannot create: " + ec.message());
  impl->env->ResetAll(0);
  std::ofstream(out_dir + "/config.json") << config.ToJson().dump(2) << "\n";
  return std::unique_ptr<PpoTrainer>(new PpoTrainer(std::move(impl)));
}

core::StatusOr<std::unique_ptr<PpoTrainer>> PpoTrainer::Resume(const std::string& out_dir,
                                                               int64_t total_steps) {
  std::string path = (fs::path(out_dir) / kCheckpointName).string();
  if (!std::ifstream(path).good()) {
    return absl::NotFoundError(path + ": no checkpoint to resume from");
  }
  auto impl = std::make_unique<Impl>();
  impl->out = out_dir;
  try {
    torch::serialize::InputArchive ar;
    ar.load_from(path);
    c10::IValue cfg_json, rng, iteration, env_steps, episodes, wall, best, curriculum;
    if (!ar.try_read("config", cfg_json) || !ar.try_read("rng", rng) ||
        !ar.try_read("iteration", iteration) || !ar.try_read("env_steps", env_steps) ||
        !ar.try_read("episodes", episodes) || !ar.try_read("wall_s", wall) ||
        !ar.try_read("best_success", best) || !ar.try_read("curriculum", curriculum)) {
      return absl::DataLossError(path + ": not a training checkpoint (training state missing)");
    }
    nlohmann::json j = nlohmann::json::parse(cfg_json.toStringRef(), nullptr, false);
    auto cfg = PpoConfig::FromCheckpointJson(j);
    if (!cfg.ok()) return core::Annotate(cfg.status(), path + ": config");
    impl->cfg = *cfg;
    if (total_steps > 0) impl->cfg.total_steps = total_steps;
    SH_ASSIGN_OR_RETURN(std::unique_ptr<VecTask> task,
                        MakeTask(impl->cfg.task, impl->cfg.num_envs, impl->cfg.physics_solver));
    impl->env = std::make_unique<VecEnv>(std::move(task), impl->cfg.threads, impl->cfg.seed);
    impl->Build();
    SH_RETURN_IF_ERROR(impl->BuildAmp());
    auto meta = control::ReadPolicyMeta(ar);
    if (!meta.ok()) return core::Annotate(meta.status(), path);
    if (meta->obs_dim != impl->env->obs_dim() || meta->act_dim != impl->env->act_dim() ||
        meta->hidden != impl->cfg.hidden || meta->task != impl->cfg.task) {
      return absl::DataLossError(path + ": network shape or task differs from its config");
    }
    torch::serialize::InputArchive a, c, o;
    if (!ar.try_read("actor", a) || !ar.try_read("critic", c) || !ar.try_read("optim", o)) {
      return absl::DataLossError(path + ": actor, critic or optimizer state missing");
    }
    impl->actor->load(a);
    // torch's load replaces a parameter whatever its shape: compare with the built critic
    std::vector<std::vector<int64_t>> built;
    for (const auto& p : impl->critic->parameters()) built.push_back(p.sizes().vec());
    impl->critic->load(c);
    std::vector<torch::Tensor> loaded = impl->critic->parameters();
    for (size_t k = 0; k < loaded.size(); ++k) {
      if (loaded[k].sizes().vec() != built[k]) {
        return absl::DataLossError(path +
                                   ": the value network's shape differs from its config "
                                   "(critic_hidden)");
      }
    }
    impl->opt->load(o);
    if (impl->amp) {
      torch::serialize::InputArchive d, dopt;
      if (!ar.try_read("amp_disc", d) || !ar.try_read("amp_optim", dopt)) {
        return absl::DataLossError(path +
                                   ": the config has amp_clips but the checkpoint holds no "
                                   "discriminator (amp_disc, amp_optim)");
      }
      impl->amp->disc->load(d);
      impl->amp->opt->load(dopt);
    }
    SH_RETURN_IF_ERROR(core::Annotate(impl->norm.Load(ar, impl->env->obs_dim()), path));
    std::istringstream r(rng.toStringRef());
    r >> impl->rng.engine();
    if (r.fail()) return absl::DataLossError(path + ": corrupt RNG state");
    impl->iteration = iteration.toInt();
    impl->env_steps = env_steps.toInt();
    impl->episodes = episodes.toInt();
    impl->wall_s = wall.toDouble();
    impl->best_success = best.toDouble();
    impl->env->task().set_curriculum(curriculum.toDouble());
    for (const auto& p : impl->Params()) {
      if (!torch::isfinite(p).all().item<bool>()) {
        return absl::DataLossError(path + ": non-finite network weights");
      }
    }
  } catch (const c10::Error& e) {
    return absl::DataLossError(path + ": corrupt checkpoint: " + e.what_without_backtrace());
  } catch (const std::exception& e) {
    return absl::DataLossError(path + ": corrupt checkpoint: " + e.what());
  }
  // iterations logged after the checkpoint were lost with the process: drop their lines
  {
    std::string log_path = out_dir + "/log.jsonl";
    std::ifstream in(log_path);
    std::string line, kept;
    while (std::getline(in, line)) {
      nlohmann::json j = nlohmann::json::parse(line, nullptr, false);
      if (j.is_object() && j.value("env_steps", int64_t{0}) <= impl->env_steps) kept += line + "\n";
    }
    in.close();
    std::ofstream(log_path + ".tmp") << kept;
    std::error_code ec;
    fs::rename(log_path + ".tmp", log_path, ec);
  }
  // new episodes after a resume get fresh seeds
  impl->env->ResetAll(static_cast<uint64_t>(impl->iteration + 1) << 24);
  return std::unique_ptr<PpoTrainer>(new PpoTrainer(std::move(impl)));
}

absl::Status PpoTrainer::Checkpoint() {
  Impl& m = *impl_;
  SH_RETURN_IF_ERROR(m.WriteCheckpoint(m.out + "/" + kCheckpointName));
  SH_RETURN_IF_ERROR(m.WritePolicy(m.out + "/policy.pt"));
  if (m.window.size() >= 50) {
    double s = 0;
    for (const auto& e : m.window) s += e.success;
    s /= m.window.size();
    if (s >= m.best_success) {
      m.best_success = s;
      SH_RETURN_IF_ERROR(m.WritePolicy(m.out + "/best_policy.pt"));
    }
  }
  m.last_ckpt = Clock::now();
  return absl::OkStatus();
}

core::StatusOr<IterationStats> PpoTrainer::Iterate() {
  Impl& m = *impl_;
  auto t0 = Clock::now();
  const int E = m.env->num_envs(), D = m.env->obs_dim(), A = m.env->act_dim();
  const int T = m.cfg.rollout_steps;
  const float gamma = static_cast<float>(m.cfg.gamma);
  torch::Tensor b_obs = torch::empty({T, E, D});
  torch::Tensor b_act = torch::empty({T, E, A});
  torch::Tensor b_logp = torch::empty({T, E});
  torch::Tensor b_val = torch::empty({T, E});
  torch::Tensor b_rew = torch::empty({T, E});
  torch::Tensor b_done = torch::empty({T, E});
  const int F = m.amp ? m.env->amp_feature_dim() : 0;
  torch::Tensor b_amp = m.amp ? torch::empty({T, E, 2 * F}) : torch::Tensor();
  double style_sum = 0, task_sum = 0;
  IterationStats st;

  // rollout
  {
    torch::NoGradGuard ng;
    m.actor->eval();
    torch::Tensor log_std = m.actor->log_std();
    torch::Tensor std_dev = torch::exp(log_std);
    for (int t = 0; t < T; ++t) {
      torch::Tensor raw = torch::from_blob(const_cast<float*>(m.env->obs().data()), {E, D});
      m.norm.Update(raw);
      // the exploration noise is drawn here, in env order, so results do not depend on chunks
      torch::Tensor noise = m.Gaussian(E, A);
      torch::Tensor t_obs = b_obs[t], t_act = b_act[t], t_logp = b_logp[t], t_val = b_val[t];
      // policy and value of envs [b, e): reads their raw observations, fills the buffers
      auto infer = [&](int b, int e, const float* obs_rows, float* act_rows) {
        torch::NoGradGuard ng_thread;  // grad mode is per thread
        torch::Tensor o = m.norm.Normalize(torch::from_blob(
            const_cast<float*>(obs_rows) + static_cast<int64_t>(b) * D, {e - b, D}));
        torch::Tensor mean = m.actor->forward(o);
        torch::Tensor act = mean + std_dev * noise.slice(0, b, e);
        t_obs.slice(0, b, e).copy_(o);
        t_act.slice(0, b, e).copy_(act);
        t_logp.slice(0, b, e).copy_(LogProb(act, mean, log_std, m.act_used));
        t_val.slice(0, b, e).copy_(m.critic->forward(o).squeeze(-1));
        torch::from_blob(act_rows + static_cast<int64_t>(b) * A, {e - b, A}).copy_(act);
      };
      if (m.cfg.rollout_chunks > 0) {
        m.env->StepChunked(
            [&](int b, int e, const float* obs_rows, float* act_rows) {
              // OpenMP thread counts are per thread (LibTorch's and OpenBLAS's): one per worker
              if (omp_get_max_threads() != 1) omp_set_num_threads(1);
              infer(b, e, obs_rows, act_rows);
            },
            m.cfg.rollout_chunks);
      } else {
        std::vector<float> actions(static_cast<size_t>(E) * A);
        infer(0, E, m.env->obs().data(), actions.data());
        m.env->Step(actions.data());
      }
      torch::Tensor rew =
          torch::from_blob(const_cast<float*>(m.env->rewards().data()), {E}).clone();
      if (m.amp) {
        // style reward of the step's (s_t, s_t+1); the time-limit bootstrap below is added
        // to the mixed reward
        torch::Tensor pairs =
            torch::from_blob(const_cast<float*>(m.env->amp_pairs().data()), {E, 2 * F}).clone();
        torch::Tensor style = AmpStyleReward(m.amp->disc, pairs);
        b_amp[t] = pairs;
        style_sum += style.sum().item<double>();
        task_sum += rew.sum().item<double>();
        rew = static_cast<float>(m.cfg.amp_task_weight) * rew +
              static_cast<float>(m.cfg.amp_style_weight) * style;
      }
      torch::Tensor done = torch::zeros({E});
      std::vector<int64_t> trunc;
      for (int i = 0; i < E; ++i) {
        if (m.env->terminated()[i] || m.env->truncated()[i]) done[i] = 1.f;
        if (m.env->truncated()[i]) trunc.push_back(i);
      }
      // time limits: bootstrap with the value of the last observation
      if (!trunc.empty()) {
        torch::Tensor term =
            torch::from_blob(const_cast<float*>(m.env->terminal_obs().data()), {E, D});
        torch::Tensor idx = torch::tensor(trunc, torch::kInt64);
        torch::Tensor v =
            m.critic->forward(m.norm.Normalize(term.index_select(0, idx))).squeeze(-1);
        rew.index_add_(0, idx, gamma * v);
      }
      b_rew[t] = rew;
      b_done[t] = done;
      for (const EpisodeStats& e : m.env->finished()) {
        m.window.push_back(e);
        if (m.window.size() > kStatsWindow) m.window.pop_front();
        ++m.episodes;
        ++m.curr_count;
        m.curr_success += e.success;
      }
    }
    torch::Tensor last = torch::from_blob(const_cast<float*>(m.env->obs().data()), {E, D});
    torch::Tensor last_v = m.critic->forward(m.norm.Normalize(last)).squeeze(-1);
    // GAE
    torch::Tensor adv = torch::zeros({T, E});
    torch::Tensor gae = torch::zeros({E});
    for (int t = T - 1; t >= 0; --t) {
      torch::Tensor next_v = t == T - 1 ? last_v : b_val[t + 1];
      torch::Tensor nonterm = 1.f - b_done[t];
      torch::Tensor delta = b_rew[t] + gamma * next_v * nonterm - b_val[t];
      gae = delta + gamma * static_cast<float>(m.cfg.lambda) * nonterm * gae;
      adv[t] = gae;
    }
    b_rew = adv + b_val;  // returns
    b_done = adv;
  }
  m.env_steps += static_cast<int64_t>(T) * E;
  auto t1 = Clock::now();
  // the env threads are idle during the update: it gets the cores
  torch::set_num_threads(m.cfg.update_torch_threads);

  // curriculum: widen when more than half of recent episodes succeed
  m.curr_steps += static_cast<int64_t>(T) * E;
  bool raise = m.cfg.curriculum_max_steps > 0 && m.curr_steps >= m.cfg.curriculum_max_steps;
  if (m.curr_count >= 64) {
    raise = raise || m.curr_success > m.curr_count / 2;
    m.curr_count = m.curr_success = 0;
  }
  if (raise && m.env->task().curriculum() < 1.0) {
    m.env->task().set_curriculum(std::min(1.0, m.env->task().curriculum() + 1.0 / 9.0));
    m.curr_steps = 0;
  }

  // update
  const int64_t N = static_cast<int64_t>(T) * E;
  torch::Tensor obs = b_obs.reshape({N, D}), act = b_act.reshape({N, A});
  torch::Tensor old_logp = b_logp.reshape({N}), old_v = b_val.reshape({N});
  torch::Tensor ret = b_rew.reshape({N}), adv = b_done.reshape({N});
  adv = (adv - adv.mean()) / (adv.std() + 1e-8);
  double lr = m.Lr();
  for (auto& g : m.opt->param_groups()) {
    static_cast<torch::optim::AdamOptions&>(g.options()).lr(lr);
  }
  bool rollout_finite = torch::isfinite(obs).all().item<bool>() &&
                        torch::isfinite(ret).all().item<bool>() &&
                        torch::isfinite(adv).all().item<bool>();
  std::vector<torch::Tensor> params = m.Params();
  std::vector<torch::Tensor> backup;
  for (const auto& p : params) backup.push_back(p.detach().clone());
  m.actor->train();
  double pl = 0, vl = 0, ent = 0, kl = 0, cf = 0;
  int n_mb = 0, skipped = 0;
  const int64_t mb = N / m.cfg.minibatches;
  std::vector<int64_t> perm(N);
  // a run started from a given policy first fits its fresh value network
  const bool critic_only = !m.cfg.init_from.empty() && m.iteration < m.cfg.critic_warmup_iters;
  for (int ep = 0; ep < m.cfg.epochs && rollout_finite; ++ep) {
    std::iota(perm.begin(), perm.end(), 0);
    std::shuffle(perm.begin(), perm.end(), m.rng.engine());
    torch::Tensor perm_t = torch::tensor(perm, torch::kInt64);
    for (int k = 0; k < m.cfg.minibatches; ++k) {
      torch::Tensor idx = perm_t.slice(0, k * mb, (k + 1) * mb);
      torch::Tensor o = obs.index_select(0, idx), a = act.index_select(0, idx);
      torch::Tensor olp = old_logp.index_select(0, idx), ov = old_v.index_select(0, idx);
      torch::Tensor r = ret.index_select(0, idx), ad = adv.index_select(0, idx);
      torch::Tensor mean = m.actor->forward(o);
      torch::Tensor log_std = m.actor->log_std();
      torch::Tensor logp = LogProb(a, mean, log_std, m.act_used);
      torch::Tensor ratio = torch::exp(logp - olp);
      torch::Tensor pg =
          -torch::min(ratio * ad, torch::clamp(ratio, 1 - m.cfg.clip, 1 + m.cfg.clip) * ad).mean();
      torch::Tensor v = m.critic->forward(o).squeeze(-1);
      torch::Tensor vc = ov + torch::clamp(v - ov, -m.cfg.value_clip, m.cfg.value_clip);
      torch::Tensor vloss = 0.5 * torch::max((v - r).pow(2), (vc - r).pow(2)).mean();
      torch::Tensor entropy = ((log_std + 0.5 + 0.5 * kLog2Pi) * m.act_used).sum();
      torch::Tensor loss = critic_only
                               ? m.cfg.value_coef * vloss
                               : pg + m.cfg.value_coef * vloss - m.cfg.entropy_coef * entropy;
      if (!torch::isfinite(loss).item<bool>()) {
        ++skipped;
        continue;
      }
      m.opt->zero_grad();
      loss.backward();
      double gn = torch::nn::utils::clip_grad_norm_(params, m.cfg.max_grad_norm);
      if (!std::isfinite(gn)) {
        ++skipped;
        m.opt->zero_grad();
        continue;
      }
      m.opt->step();
      torch::NoGradGuard ng;
      pl += pg.item<double>();
      vl += vloss.item<double>();
      ent += entropy.item<double>();
      torch::Tensor lr_ = logp.detach() - olp;
      kl += ((torch::exp(lr_) - 1) - lr_).mean().item<double>();
      cf += (torch::abs(ratio.detach() - 1) > m.cfg.clip).to(torch::kFloat32).mean().item<double>();
      ++n_mb;
    }
  }
  // NaN guard: a non-finite rollout or weights -> restore and count; abort after several
  bool params_finite = true;
  for (const auto& p : params)
    params_finite = params_finite && torch::isfinite(p).all().item<bool>();
  if (!rollout_finite || !params_finite || skipped > 0) {
    if (!params_finite) {
      torch::NoGradGuard ng;
      for (size_t i = 0; i < params.size(); ++i) params[i].copy_(backup[i]);
    }
    if (!rollout_finite) skipped = m.cfg.epochs * m.cfg.minibatches;
    if (++m.bad_in_row >= m.cfg.max_bad_updates) {
      torch::set_num_threads(m.cfg.torch_threads);
      return absl::InternalError("training aborted: " + std::to_string(m.bad_in_row) +
                                 " non-finite updates in a row at iteration " +
                                 std::to_string(m.iteration));
    }
  } else {
    m.bad_in_row = 0;
  }
  // discriminator: agent pairs of this rollout into the replay buffer, then a few updates
  if (m.amp) {
    m.amp->replay->Add(b_amp.reshape({N, 2 * F}));
    AmpUpdateStats sum;
    int n_ok = 0;
    for (int k = 0; k < m.cfg.amp_disc_updates; ++k) {
      torch::Tensor e = SampleRows(m.amp->expert, m.cfg.amp_disc_batch, m.rng);
      torch::Tensor a = m.amp->replay->Sample(m.cfg.amp_disc_batch, m.rng);
      AmpUpdateStats s1;
      if (!AmpUpdate(m.amp->disc, *m.amp->opt, e, a, m.cfg.amp_grad_penalty, m.cfg.max_grad_norm,
                     &s1)) {
        ++st.amp_skipped;
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
    st.amp = true;
    if (n_ok > 0) {
      st.amp_disc_loss = sum.loss / n_ok;
      st.amp_grad_penalty = sum.grad_penalty / n_ok;
      st.amp_expert_acc = sum.expert_acc / n_ok;
      st.amp_agent_acc = sum.agent_acc / n_ok;
      st.amp_d_expert = sum.d_expert / n_ok;
      st.amp_d_agent = sum.d_agent / n_ok;
    }
    st.amp_style_reward = style_sum / static_cast<double>(N);
    st.amp_task_reward = task_sum / static_cast<double>(N);
  }
  torch::set_num_threads(m.cfg.torch_threads);
  auto t2 = Clock::now();
  ++m.iteration;
  double collect = std::chrono::duration<double>(t1 - t0).count();
  double update = std::chrono::duration<double>(t2 - t1).count();
  m.wall_s += collect + update;

  st.iteration = m.iteration;
  st.env_steps = m.env_steps;
  st.wall_s = m.wall_s;
  st.episodes = m.episodes;
  if (!m.window.empty()) {
    for (const auto& e : m.window) {
      st.mean_return += e.ret;
      st.mean_length += e.length;
      st.success_rate += e.success;
      st.fall_rate += e.terminated;
    }
    double n = static_cast<double>(m.window.size());
    st.mean_return /= n;
    st.mean_length /= n;
    st.success_rate /= n;
    st.fall_rate /= n;
  }
  if (n_mb > 0) {
    st.policy_loss = pl / n_mb;
    st.value_loss = vl / n_mb;
    st.entropy = ent / n_mb;
    st.approx_kl = kl / n_mb;
    st.clip_frac = cf / n_mb;
  }
  st.lr = lr;
  st.action_std =
      ((torch::exp(m.actor->log_std()) * m.act_used).sum() / m.act_used.sum()).item<double>();
  st.curriculum = m.env->task().curriculum();
  st.collect_s = collect;
  st.update_s = update;
  st.steps_per_s = static_cast<double>(N) / std::max(1e-9, collect + update);
  st.skipped_minibatches = skipped;
  if (std::chrono::duration<double>(Clock::now() - m.last_ckpt).count() >=
          m.cfg.checkpoint_every_s ||
      done()) {
    SH_RETURN_IF_ERROR(Checkpoint());
    st.checkpointed = true;
  }
  m.AppendLog(st);
  return st;
}

absl::Status ExportPolicy(const std::string& checkpoint, const std::string& out) {
  auto p = control::LoadPolicyFile(checkpoint);
  if (!p.ok()) return p.status();
  try {
    torch::serialize::OutputArchive ar;
    control::SavePolicyKeys(ar, p->meta, p->actor, p->norm);
    auto progress = ReadCheckpointProgress(checkpoint);
    if (progress.ok()) ar.write("env_steps", c10::IValue(progress->first));
    return SaveAtomic(ar, out);
  } catch (const c10::Error& e) {
    return absl::InternalError(out + ": " + e.what_without_backtrace());
  }
}

}  // namespace simhuman::learn

namespace simhuman::learn {

core::StatusOr<std::pair<int64_t, double>> ReadCheckpointProgress(const std::string& path) {
  try {
    torch::serialize::InputArchive ar;
    ar.load_from(path);
    c10::IValue steps, wall;
    if (!ar.try_read("env_steps", steps)) {
      return absl::DataLossError(path + ": no env_steps in the file");
    }
    double w = ar.try_read("wall_s", wall) ? wall.toDouble() : 0.0;
    return std::make_pair(static_cast<int64_t>(steps.toInt()), w);
  } catch (const c10::Error& e) {
    return absl::DataLossError(path + ": corrupt or unreadable: " + e.what_without_backtrace());
  }
}

}  // namespace simhuman::learn
