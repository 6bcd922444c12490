#include "simhuman/learn/mappo.h"

#include <torch/torch.h>

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <fstream>

#include "simhuman/control/policy/policy_net.h"
#include "simhuman/core/rng.h"
#include "simhuman/learn/multi_agent_env.h"
#include "simhuman/learn/multi_agent_tasks.h"
#include "simhuman/learn/ppo_checkpoint.h"
#include "simhuman/learn/ppo_rollout.h"
#include "simhuman/learn/ppo_update.h"
#include "simhuman/learn/team_rollout.h"

namespace simhuman::learn {
namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

namespace {

constexpr char kCheckpointName[] = "checkpoint.pt";
constexpr size_t kStatsWindow = 200;
constexpr uint64_t kRngStream = 0x4d41;  // the trainer RNG's stream (PpoTrainer's is 0x5050)

}  // namespace

struct MappoTrainer::Impl {
  MappoConfig cfg;
  std::string out;
  std::unique_ptr<MultiAgentVecEnv> env;
  ActorCritic net;
  control::ObsNormalizer obs_norm;
  CriticInput critic_in;
  core::Rng rng{0};
  TrainingProgress progress;
  NonFiniteGuard guard{1};
  EpisodeWindow window{kStatsWindow};
  Clock::time_point last_ckpt = Clock::now();

  // networks from torch::manual_seed(seed), the normalizers and the trainer's RNG
  void Build() {
    torch::set_num_threads(cfg.torch_threads);
    torch::manual_seed(cfg.seed);
    const int d = env->obs_dim(), a = env->act_dim();
    critic_in = CriticInput(env->state_dim(), env->num_agents(), d, cfg.critic_agent_obs);
    std::vector<float> used(a);
    for (int j = 0; j < a; ++j) used[j] = env->task().action_used(j) ? 1.f : 0.f;
    net = MakeActorCritic(d, critic_in.dim(), a, cfg.hidden, cfg.critic_hidden, cfg.init_std,
                          cfg.lr, used);
    obs_norm = control::ObsNormalizer(d);
    rng = core::Rng(core::DeriveSeed(cfg.seed, kRngStream));
    guard = NonFiniteGuard(cfg.max_bad_updates);
  }

  control::PolicyMeta Meta() const {
    return control::PolicyMeta{cfg.task, env->obs_dim(), env->act_dim(), cfg.hidden, ""};
  }

  double Lr() const {
    double f = std::min(
        1.0, static_cast<double>(progress.env_steps) / static_cast<double>(cfg.total_steps));
    return cfg.lr * (1.0 - (1.0 - cfg.lr_final_frac) * f);
  }

  PpoUpdateOptions UpdateOptions() const {
    PpoUpdateOptions o;
    o.epochs = cfg.epochs;
    o.minibatches = cfg.minibatches;
    o.clip = cfg.clip;
    o.value_clip = cfg.value_clip;
    o.value_coef = cfg.value_coef;
    o.entropy_coef = cfg.entropy_coef;
    o.max_grad_norm = cfg.max_grad_norm;
    return o;
  }

  absl::Status WriteCheckpoint(const std::string& path) {
    try {
      torch::serialize::OutputArchive ar, state_norm;
      control::SavePolicyKeys(ar, Meta(), net.actor, obs_norm);
      WriteLearnerState(ar, net, rng);
      progress.Write(ar);
      critic_in.state_norm().Save(state_norm);
      ar.write("state_norm", state_norm);
      ar.write("config", c10::IValue(cfg.ToJson().dump()));
      return SaveArchiveAtomic(ar, path);
    } catch (const c10::Error& e) {
      return absl::InternalError(path + ": " + e.what_without_backtrace());
    }
  }

  absl::Status WritePolicy(const std::string& path) {
    torch::serialize::OutputArchive ar;
    control::SavePolicyKeys(ar, Meta(), net.actor, obs_norm);
    ar.write("env_steps", c10::IValue(progress.env_steps));
    return SaveArchiveAtomic(ar, path);
  }

  // loads the networks, optimizer, RNG and normalizers of a checkpoint archive
  absl::Status Restore(torch::serialize::InputArchive& ar, const std::string& path) {
    auto meta = control::ReadPolicyMeta(ar);
    if (!meta.ok()) return core::Annotate(meta.status(), path);
    if (meta->obs_dim != env->obs_dim() || meta->act_dim != env->act_dim() ||
        meta->hidden != cfg.hidden || meta->task != cfg.task) {
      return absl::DataLossError(path + ": network shape or task differs from its config");
    }
    SH_RETURN_IF_ERROR(ReadLearnerState(ar, path, net, rng));
    SH_RETURN_IF_ERROR(core::Annotate(obs_norm.Load(ar, env->obs_dim()), path));
    torch::serialize::InputArchive state_norm;
    if (!ar.try_read("state_norm", state_norm)) {
      return absl::DataLossError(path + ": state_norm (the critic's state statistics) missing");
    }
    SH_RETURN_IF_ERROR(
        core::Annotate(critic_in.state_norm().Load(state_norm, env->state_dim()), path));
    return CheckFiniteWeights(net, path);
  }
};

MappoTrainer::MappoTrainer(std::unique_ptr<Impl> impl) : impl_(std::move(impl)) {}
MappoTrainer::~MappoTrainer() = default;
bool MappoTrainer::done() const { return impl_->progress.env_steps >= impl_->cfg.total_steps; }
int64_t MappoTrainer::env_steps() const { return impl_->progress.env_steps; }
const MappoConfig& MappoTrainer::config() const { return impl_->cfg; }
const std::string& MappoTrainer::out_dir() const { return impl_->out; }

core::StatusOr<std::unique_ptr<MappoTrainer>> MappoTrainer::Create(const MappoConfig& config,
                                                                   const std::string& out_dir) {
  SH_RETURN_IF_ERROR(config.Validate());
  SH_ASSIGN_OR_RETURN(std::unique_ptr<MultiAgentVecTask> task,
                      MakeMultiAgentTask(config.task, config.num_envs, config.num_agents));
  return CreateWithTask(config, out_dir, std::move(task));
}

core::StatusOr<std::unique_ptr<MappoTrainer>> MappoTrainer::CreateWithTask(
    const MappoConfig& config, const std::string& out_dir,
    std::unique_ptr<MultiAgentVecTask> task) {
  SH_RETURN_IF_ERROR(config.Validate());
  if (task->num_agents() != config.num_agents || task->num_envs() != config.num_envs) {
    return absl::InvalidArgumentError(
        "task '" + task->name() + "' has " + std::to_string(task->num_envs()) + " envs of " +
        std::to_string(task->num_agents()) + " agents but the config says num_envs " +
        std::to_string(config.num_envs) + ", num_agents " + std::to_string(config.num_agents));
  }
  std::error_code ec;
  if (fs::exists(fs::path(out_dir) / kCheckpointName, ec)) {
    return absl::AlreadyExistsError(out_dir +
                                    " already holds a checkpoint; resume it or choose another "
                                    "output folder");
  }
  auto impl = std::make_unique<Impl>();
  impl->cfg = config;
  impl->out = out_dir;
  impl->env = std::make_unique<MultiAgentVecEnv>(std::move(task), config.threads, config.seed);
  impl->Build();
  fs::create_directories(out_dir, ec);
  if (ec) return absl::PermissionDeniedError(out_dir + ": cannot create: " + ec.message());
  impl->env->ResetAll(0);
  std::ofstream(out_dir + "/config.json") << config.ToJson().dump(2) << "\n";
  return std::unique_ptr<MappoTrainer>(new MappoTrainer(std::move(impl)));
}

core::StatusOr<std::unique_ptr<MappoTrainer>> MappoTrainer::Resume(const std::string& out_dir,
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
    c10::IValue cfg_json;
    if (!ar.try_read("config", cfg_json) || !impl->progress.Read(ar)) {
      return absl::DataLossError(path + ": not a training checkpoint (training state missing)");
    }
    nlohmann::json j = nlohmann::json::parse(cfg_json.toStringRef(), nullptr, false);
    auto cfg = MappoConfig::FromJson(j, "/config");
    if (!cfg.ok()) return core::Annotate(cfg.status(), path);
    impl->cfg = *cfg;
    if (total_steps > 0) impl->cfg.total_steps = total_steps;
    SH_ASSIGN_OR_RETURN(
        std::unique_ptr<MultiAgentVecTask> task,
        MakeMultiAgentTask(impl->cfg.task, impl->cfg.num_envs, impl->cfg.num_agents));
    impl->env =
        std::make_unique<MultiAgentVecEnv>(std::move(task), impl->cfg.threads, impl->cfg.seed);
    impl->Build();
    SH_RETURN_IF_ERROR(impl->Restore(ar, path));
  } catch (const c10::Error& e) {
    return absl::DataLossError(path + ": corrupt checkpoint: " + e.what_without_backtrace());
  } catch (const std::exception& e) {
    return absl::DataLossError(path + ": corrupt checkpoint: " + e.what());
  }
  TrimLogAfter(out_dir + "/log.jsonl", impl->progress.env_steps);
  // new episodes after a resume get fresh seeds
  impl->env->ResetAll(static_cast<uint64_t>(impl->progress.iteration + 1) << 24);
  return std::unique_ptr<MappoTrainer>(new MappoTrainer(std::move(impl)));
}

absl::Status MappoTrainer::Checkpoint() {
  Impl& m = *impl_;
  SH_RETURN_IF_ERROR(m.WriteCheckpoint(m.out + "/" + kCheckpointName));
  SH_RETURN_IF_ERROR(m.WritePolicy(m.out + "/policy.pt"));
  m.last_ckpt = Clock::now();
  return absl::OkStatus();
}

core::StatusOr<IterationStats> MappoTrainer::Iterate() {
  Impl& m = *impl_;
  auto t0 = Clock::now();
  const int64_t steps = static_cast<int64_t>(m.cfg.rollout_steps) * m.env->num_envs();
  const float gamma = static_cast<float>(m.cfg.gamma);
  RolloutBuffer rollout =
      CollectTeamRollout(*m.env, m.net, m.obs_norm, m.critic_in, m.rng, m.cfg.rollout_steps, gamma,
                         [&m](const TeamEpisodeStats& e) {
                           m.window.Add(e.team);
                           ++m.progress.episodes;
                         });
  PpoBatch batch = rollout.Finish(gamma, static_cast<float>(m.cfg.lambda));
  m.progress.env_steps += steps;
  auto t1 = Clock::now();

  const double lr = m.Lr();
  SetLearningRate(*m.net.opt, lr);
  m.guard.Begin(m.net.Params());
  PpoUpdateStats up = PpoUpdate(m.net, batch, m.UpdateOptions(), m.rng);
  SH_RETURN_IF_ERROR(m.guard.End(up, m.progress.iteration));
  auto t2 = Clock::now();
  ++m.progress.iteration;
  const double collect = std::chrono::duration<double>(t1 - t0).count();
  const double update = std::chrono::duration<double>(t2 - t1).count();
  m.progress.wall_s += collect + update;

  IterationStats st;
  st.iteration = m.progress.iteration;
  st.env_steps = m.progress.env_steps;
  st.wall_s = m.progress.wall_s;
  st.episodes = m.progress.episodes;
  EpisodeMeans e = m.window.Means();
  st.mean_return = e.ret;
  st.mean_length = e.length;
  st.success_rate = e.success;
  st.fall_rate = e.fall;
  st.policy_loss = up.policy_loss;
  st.value_loss = up.value_loss;
  st.entropy = up.entropy;
  st.approx_kl = up.approx_kl;
  st.clip_frac = up.clip_frac;
  st.skipped_minibatches = up.skipped;
  st.stepped_minibatches = up.minibatches;
  st.lr = lr;
  st.action_std = m.net.ActionStd();
  st.curriculum = 1.0;
  st.collect_s = collect;
  st.update_s = update;
  st.steps_per_s = static_cast<double>(steps) / std::max(1e-9, collect + update);
  if (std::chrono::duration<double>(Clock::now() - m.last_ckpt).count() >=
          m.cfg.checkpoint_every_s ||
      done()) {
    SH_RETURN_IF_ERROR(Checkpoint());
    st.checkpointed = true;
  }
  AppendJsonLine(m.out + "/log.jsonl", st.ToJson());
  return st;
}

}  // namespace simhuman::learn
