#include "simhuman/learn/ppo.h"

#include <torch/torch.h>

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <fstream>

#include "simhuman/control/policy/policy_net.h"
#include "simhuman/core/rng.h"
#include "simhuman/learn/data_parallel.h"
#include "simhuman/learn/ppo_amp.h"
#include "simhuman/learn/ppo_checkpoint.h"
#include "simhuman/learn/ppo_rollout.h"
#include "simhuman/learn/ppo_update.h"
#include "simhuman/learn/tasks.h"
#include "simhuman/learn/vec_env.h"
#include "simhuman/learn/walk_env.h"

namespace simhuman::learn {
namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

namespace {

constexpr char kCheckpointName[] = "checkpoint.pt";
constexpr size_t kStatsWindow = 200;
constexpr size_t kBestPolicyMinEpisodes = 50;

core::StatusOr<std::unique_ptr<VecTask>> MakeTask(const std::string& name, int envs,
                                                  const TaskOptions& options) {
  SH_ASSIGN_OR_RETURN(const TaskDef* def, FindTask(name));
  return def->make(envs, options);
}

TaskOptions OptionsOf(const PpoConfig& c) {
  TaskOptions o;
  o.solver = c.physics_solver;
  o.body_scales = c.body_scales;
  o.walk_gait = c.walk_gait;
  o.carry_grip = c.carry_grip;
  o.carry_held_start_frac = c.carry_held_start_frac;
  o.carry_put_down_start_frac = c.carry_put_down_start_frac;
  o.walk_gait_weight = c.walk_gait_weight;
  o.walk_gait_width = c.walk_gait_width;
  o.walk_foot_slip_weight = c.walk_foot_slip_weight;
  o.walk_route_share = c.walk_route_share;
  return o;
}

std::string Widths(const std::vector<int>& h) {
  std::string s;
  for (int x : h) s += (s.empty() ? "" : ",") + std::to_string(x);
  return s;
}

}  // namespace

nlohmann::json IterationStats::ToJson() const {
  nlohmann::json j{{"iteration", iteration},
                   {"env_steps", env_steps},
                   {"wall_s", wall_s},
                   {"return", mean_return},
                   {"ep_length", mean_length},
                   {"success", success_rate},
                   {"fall", fall_rate},
                   {"episodes", episodes},
                   {"policy_loss", policy_loss},
                   {"value_loss", value_loss},
                   {"entropy", entropy},
                   {"approx_kl", approx_kl},
                   {"clip_frac", clip_frac},
                   {"lr", lr},
                   {"action_std", action_std},
                   {"curriculum", curriculum},
                   {"steps_per_s", steps_per_s},
                   {"collect_s", collect_s},
                   {"update_s", update_s},
                   {"skipped", skipped_minibatches},
                   {"minibatches", stepped_minibatches}};
  if (ranks > 1) {
    j["ranks"] = ranks;
    j["allreduce_calls"] = allreduce_calls;
    j["allreduce_bytes"] = allreduce_bytes;
    j["allreduce_s"] = allreduce_s;
    j["sync_s"] = sync_s;
    j["rank_rollout_s"] = rank_rollout_s;
  }
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
  ActorCritic net;
  control::ObsNormalizer norm;
  core::Rng rng{0};
  TrainingProgress progress;
  NonFiniteGuard guard{1};
  EpisodeWindow window{kStatsWindow};
  int curr_count = 0, curr_success = 0;  // episodes since the last curriculum check
  int64_t curr_steps = 0;                // env steps at the current level
  Clock::time_point last_ckpt = Clock::now();
  std::unique_ptr<AmpStage> amp;  // null when AMP is off
  core::SerialCommunicator serial;
  core::Communicator* comm = &serial;  // the ranks of a data-parallel run (not owned)

  int rank() const { return comm->rank(); }
  // rank 0 keeps the single-process seeds; the others get their own streams
  uint64_t EnvSeed() const {
    return rank() == 0 ? cfg.seed : core::DeriveSeed(cfg.seed, 0xD15, rank());
  }
  uint64_t RngSeed(uint64_t iteration) const {
    return rank() == 0 ? core::DeriveSeed(cfg.seed, 0x5050)
                       : core::DeriveSeed(cfg.seed, 0x5050, rank(), iteration);
  }
  absl::Status CheckRanks() const {
    if (comm->size() > 1 && !cfg.amp_clips.empty()) {
      return absl::InvalidArgumentError(
          "AMP (amp_clips) runs on one rank only; run it without mpirun, or drop --amp-clips");
    }
    return absl::OkStatus();
  }

  // " (it may start from a 'walk' or 'carry' policy)", or "" for a task that only starts from
  // its own
  static std::string InitSources(const TaskDef& def) {
    std::vector<std::string> from;
    if (!def.init_parent.empty()) from.push_back("'" + def.init_parent + "'");
    for (const std::string& p : def.init_peers) from.push_back("'" + p + "'");
    if (from.empty()) return "";
    std::string list = from[0];
    for (size_t k = 1; k < from.size(); ++k) list += " or " + from[k];
    return " (it may start from a " + list + " policy)";
  }

  // copies the policy of cfg.init_from (if any) into the fresh actor and normalizer
  absl::Status InitFrom() {
    if (cfg.init_from.empty()) return absl::OkStatus();
    const std::string where = "init_from '" + cfg.init_from + "'";
    core::StatusOr<control::LoadedPolicy> p = control::LoadPolicyFile(cfg.init_from);
    if (!p.ok())
      return absl::InvalidArgumentError(where + ": " + std::string(p.status().message()));
    const int d = env->obs_dim(), a = env->act_dim();
    SH_ASSIGN_OR_RETURN(const TaskDef* def, FindTask(cfg.task));
    const bool parent =
        !def->init_parent.empty() && p->meta.task == def->init_parent && p->meta.obs_dim < d;
    const bool peer = std::find(def->init_peers.begin(), def->init_peers.end(), p->meta.task) !=
                      def->init_peers.end();
    if ((p->meta.task != cfg.task && !parent && !peer) || (!parent && p->meta.obs_dim != d) ||
        p->meta.act_dim != a || p->meta.hidden != cfg.hidden) {
      return absl::InvalidArgumentError(
          where + " holds a '" + p->meta.task + "' policy (obs " + std::to_string(p->meta.obs_dim) +
          ", act " + std::to_string(p->meta.act_dim) + ", hidden " + Widths(p->meta.hidden) +
          ") but this run is '" + cfg.task + "' (obs " + std::to_string(d) + ", act " +
          std::to_string(a) + ", hidden " + Widths(cfg.hidden) + ")" + InitSources(*def) +
          "; set \"hidden\" to match");
    }
    if (TaskHasWalkGait(cfg.task) && TaskHasWalkGait(p->meta.task) &&
        p->meta.variant != cfg.walk_gait) {
      return absl::InvalidArgumentError(
          where + " walks the gait '" + p->meta.variant + "' but this run's walk_gait is '" +
          cfg.walk_gait + "'; set \"walk_gait\": \"" + p->meta.variant +
          "\" in the config so the run walks the reference the policy learned");
    }
    torch::NoGradGuard no_grad;
    auto src = p->actor->named_parameters();
    for (auto& dst : net.actor->named_parameters()) {
      const torch::Tensor* s = src.find(dst.key());
      torch::Tensor t = dst.value();
      // the input layer of a parent task's policy: its columns first, zeros for the new inputs
      const bool widen = parent && s && s->dim() == 2 && t.dim() == 2 && s->size(0) == t.size(0) &&
                         s->size(1) == p->meta.obs_dim && t.size(1) == d;
      if (widen) {
        t.zero_();
        t.narrow(1, 0, p->meta.obs_dim).copy_(*s);
        continue;
      }
      if (!s || s->sizes() != t.sizes()) {
        return absl::InvalidArgumentError(where + ": parameter '" + dst.key() +
                                          "' missing or of another shape");
      }
      t.copy_(*s);
    }
    if (parent) {
      norm = p->norm.Widened(d);
      return ResetParentUnusedActions(*def, a);
    }
    norm = p->norm;
    return absl::OkStatus();
  }

  // actions the parent task ignores (the walking policy's arms follow its reference) were never
  // trained: their output rows start at zero (the reference) and their std at the mean of the
  // trained ones
  absl::Status ResetParentUnusedActions(const TaskDef& def, int a) {
    SH_ASSIGN_OR_RETURN(const TaskDef* parent_def, FindTask(def.init_parent));
    SH_ASSIGN_OR_RETURN(std::unique_ptr<VecTask> parent_task, parent_def->make(1, TaskOptions()));
    torch::NoGradGuard no_grad;
    std::vector<int64_t> unused, used;
    for (int j = 0; j < a; ++j) (parent_task->action_used(j) ? used : unused).push_back(j);
    if (unused.empty() || used.empty()) return absl::OkStatus();
    torch::Tensor out_w, out_b, log_std;
    for (auto& prm : net.actor->named_parameters()) {
      torch::Tensor t = prm.value();
      if (prm.key() == "log_std") {
        log_std = t;
      } else if (t.dim() == 2 && t.size(0) == a) {
        out_w = t;  // the last such layer is the output layer
      } else if (t.dim() == 1 && t.size(0) == a) {
        out_b = t;
      }
    }
    if (!out_w.defined() || !out_b.defined() || !log_std.defined()) {
      return absl::InternalError("init_from: the actor has no output layer of " +
                                 std::to_string(a) + " actions");
    }
    torch::Tensor idx = torch::tensor(unused, torch::kInt64);
    out_w.index_fill_(0, idx, 0.0);
    out_b.index_fill_(0, idx, 0.0);
    const double mean_log_std =
        log_std.index_select(0, torch::tensor(used, torch::kInt64)).mean().item<double>();
    log_std.index_fill_(0, idx, mean_log_std);
    return absl::OkStatus();
  }

  // networks from torch::manual_seed(seed), the normalizer and the trainer's RNG
  void Build() {
    torch::set_num_threads(cfg.torch_threads);
    torch::manual_seed(cfg.seed);
    const int d = env->obs_dim(), a = env->act_dim();
    std::vector<float> used(a);
    for (int j = 0; j < a; ++j) used[j] = env->task().action_used(j) ? 1.f : 0.f;
    net = MakeActorCritic(d, d, a, cfg.hidden, cfg.critic_hidden, cfg.init_std, cfg.lr, used);
    norm = control::ObsNormalizer(d);
    rng = core::Rng(RngSeed(0));
    guard = NonFiniteGuard(cfg.max_bad_updates);
  }

  control::PolicyMeta Meta() const {
    return control::PolicyMeta{cfg.task,   env->obs_dim(), env->act_dim(),
                               cfg.hidden, cfg.walk_gait,  cfg.carry_grip};
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
    o.target_kl = cfg.target_kl;
    // a run started from a given policy first fits its fresh value network
    o.critic_only = !cfg.init_from.empty() && progress.iteration < cfg.critic_warmup_iters;
    return o;
  }

  void OnEpisode(const EpisodeStats& e) {
    window.Add(e);
    ++progress.episodes;
    ++curr_count;
    curr_success += e.success;
  }

  // widens the curriculum when more than half of recent episodes succeed, or after
  // curriculum_max_steps at one level
  void AdvanceCurriculum(int64_t steps) {
    curr_steps += steps;
    bool raise = cfg.curriculum_max_steps > 0 && curr_steps >= cfg.curriculum_max_steps;
    if (curr_count >= 64) {
      raise = raise || curr_success > curr_count / 2;
      curr_count = curr_success = 0;
    }
    if (raise && env->task().curriculum() < 1.0) {
      env->task().set_curriculum(std::min(1.0, env->task().curriculum() + 1.0 / 9.0));
      curr_steps = 0;
    }
  }

  absl::Status WriteCheckpoint(const std::string& path) {
    try {
      torch::serialize::OutputArchive ar;
      control::SavePolicyKeys(ar, Meta(), net.actor, norm);
      WriteLearnerState(ar, net, rng);
      progress.Write(ar);
      ar.write("curriculum", c10::IValue(env->task().curriculum()));
      ar.write("config", c10::IValue(cfg.ToJson().dump()));
      if (amp) amp->Save(ar);
      return SaveArchiveAtomic(ar, path);
    } catch (const c10::Error& e) {
      return absl::InternalError(path + ": " + e.what_without_backtrace());
    }
  }

  absl::Status WritePolicy(const std::string& path) {
    torch::serialize::OutputArchive ar;
    control::SavePolicyKeys(ar, Meta(), net.actor, norm);
    ar.write("env_steps", c10::IValue(progress.env_steps));
    return SaveArchiveAtomic(ar, path);
  }

  // loads the networks, optimizer, RNG and normalizer of a checkpoint archive (its config is
  // in cfg and its counters in progress already)
  absl::Status Restore(torch::serialize::InputArchive& ar, const std::string& path,
                       double curriculum) {
    auto meta = control::ReadPolicyMeta(ar);
    if (!meta.ok()) return core::Annotate(meta.status(), path);
    if (meta->obs_dim != env->obs_dim() || meta->act_dim != env->act_dim() ||
        meta->hidden != cfg.hidden || meta->task != cfg.task) {
      return absl::DataLossError(path + ": network shape or task differs from its config");
    }
    SH_RETURN_IF_ERROR(ReadLearnerState(ar, path, net, rng));
    if (amp) {
      SH_RETURN_IF_ERROR(amp->Load(ar, path));
    }
    SH_RETURN_IF_ERROR(core::Annotate(norm.Load(ar, env->obs_dim()), path));
    env->task().set_curriculum(curriculum);
    return CheckFiniteWeights(net, path);
  }

  // the iteration's statistics besides the update's and AMP's
  void FillStats(IterationStats* st) const {
    st->iteration = progress.iteration;
    st->env_steps = progress.env_steps;
    st->wall_s = progress.wall_s;
    st->episodes = progress.episodes;
    EpisodeMeans e = window.Means();
    st->mean_return = e.ret;
    st->mean_length = e.length;
    st->success_rate = e.success;
    st->fall_rate = e.fall;
    st->action_std = net.ActionStd();
    st->curriculum = env->task().curriculum();
  }
};

PpoTrainer::PpoTrainer(std::unique_ptr<Impl> impl) : impl_(std::move(impl)) {}
PpoTrainer::~PpoTrainer() = default;
bool PpoTrainer::done() const { return impl_->progress.env_steps >= impl_->cfg.total_steps; }
int64_t PpoTrainer::env_steps() const { return impl_->progress.env_steps; }
const PpoConfig& PpoTrainer::config() const { return impl_->cfg; }
const std::string& PpoTrainer::out_dir() const { return impl_->out; }

core::StatusOr<std::unique_ptr<PpoTrainer>> PpoTrainer::Create(const PpoConfig& config,
                                                               const std::string& out_dir,
                                                               core::Communicator* comm) {
  SH_RETURN_IF_ERROR(config.Validate());
  SH_ASSIGN_OR_RETURN(std::unique_ptr<VecTask> task,
                      MakeTask(config.task, config.num_envs, OptionsOf(config)));
  return CreateWithTask(config, out_dir, std::move(task), comm);
}

core::StatusOr<std::unique_ptr<PpoTrainer>> PpoTrainer::CreateWithTask(
    const PpoConfig& config, const std::string& out_dir, std::unique_ptr<VecTask> task,
    core::Communicator* comm) {
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
  if (comm) impl->comm = comm;
  SH_RETURN_IF_ERROR(impl->CheckRanks());
  impl->env = std::make_unique<VecEnv>(std::move(task), config.threads, impl->EnvSeed());
  impl->Build();
  SH_RETURN_IF_ERROR(impl->InitFrom());
  SH_ASSIGN_OR_RETURN(impl->amp, AmpStage::Create(config, *impl->env));
  impl->env->ResetAll(0);
  if (impl->rank() != 0) return std::unique_ptr<PpoTrainer>(new PpoTrainer(std::move(impl)));
  // the run's folder appears only once its inputs (init_from, AMP clips) have loaded
  fs::create_directories(out_dir, ec);
  if (ec) return absl::PermissionDeniedError(out_dir + ": cannot create: " + ec.message());
  std::ofstream config_file(out_dir + "/config.json");
  config_file << config.ToJson().dump(2) << "\n";
  config_file.flush();
  if (!config_file) return absl::PermissionDeniedError(out_dir + "/config.json: cannot write");
  return std::unique_ptr<PpoTrainer>(new PpoTrainer(std::move(impl)));
}

core::StatusOr<std::unique_ptr<PpoTrainer>> PpoTrainer::Resume(const std::string& out_dir,
                                                               int64_t total_steps,
                                                               core::Communicator* comm,
                                                               const nlohmann::json& changes) {
  std::string path = (fs::path(out_dir) / kCheckpointName).string();
  if (!std::ifstream(path).good()) {
    return absl::NotFoundError(path + ": no checkpoint to resume from");
  }
  auto impl = std::make_unique<Impl>();
  impl->out = out_dir;
  if (comm) impl->comm = comm;
  try {
    torch::serialize::InputArchive ar;
    ar.load_from(path);
    c10::IValue cfg_json, rng, curriculum;
    if (!ar.try_read("config", cfg_json) || !ar.try_read("rng", rng) || !impl->progress.Read(ar) ||
        !ar.try_read("curriculum", curriculum)) {
      return absl::DataLossError(path + ": not a training checkpoint (training state missing)");
    }
    nlohmann::json j = nlohmann::json::parse(cfg_json.toStringRef(), nullptr, false);
    auto cfg = changes.empty() ? PpoConfig::FromCheckpointJson(j)
                               : PpoConfig::WithResumeChanges(j, changes);
    if (!cfg.ok()) return core::Annotate(cfg.status(), path + ": config");
    impl->cfg = *cfg;
    if (total_steps > 0) impl->cfg.total_steps = total_steps;
    SH_ASSIGN_OR_RETURN(std::unique_ptr<VecTask> task,
                        MakeTask(impl->cfg.task, impl->cfg.num_envs, OptionsOf(impl->cfg)));
    SH_RETURN_IF_ERROR(impl->CheckRanks());
    impl->env = std::make_unique<VecEnv>(std::move(task), impl->cfg.threads, impl->EnvSeed());
    impl->Build();
    SH_ASSIGN_OR_RETURN(impl->amp, AmpStage::Create(impl->cfg, *impl->env));
    SH_RETURN_IF_ERROR(impl->Restore(ar, path, curriculum.toDouble()));
    // the checkpoint holds rank 0's stream; the other ranks start fresh ones
    if (impl->rank() != 0) {
      impl->rng = core::Rng(impl->RngSeed(static_cast<uint64_t>(impl->progress.iteration)));
    }
  } catch (const c10::Error& e) {
    return absl::DataLossError(path + ": corrupt checkpoint: " + e.what_without_backtrace());
  } catch (const std::exception& e) {
    return absl::DataLossError(path + ": corrupt checkpoint: " + e.what());
  }
  // iterations logged after the checkpoint were lost with the process: drop their lines
  if (impl->rank() == 0) TrimLogAfter(out_dir + "/log.jsonl", impl->progress.env_steps);
  if (impl->rank() == 0 && !changes.empty()) {
    // the run's settings from here on (the checkpoints store them too)
    std::ofstream config_file(out_dir + "/config.json");
    config_file << impl->cfg.ToJson().dump(2) << "\n";
    config_file.flush();
    if (!config_file) return absl::PermissionDeniedError(out_dir + "/config.json: cannot write");
  }
  // new episodes after a resume get fresh seeds
  impl->env->ResetAll(static_cast<uint64_t>(impl->progress.iteration + 1) << 24);
  return std::unique_ptr<PpoTrainer>(new PpoTrainer(std::move(impl)));
}

absl::Status PpoTrainer::Checkpoint() {
  Impl& m = *impl_;
  if (m.rank() != 0) return absl::OkStatus();
  SH_RETURN_IF_ERROR(m.WriteCheckpoint(m.out + "/" + kCheckpointName));
  SH_RETURN_IF_ERROR(m.WritePolicy(m.out + "/policy.pt"));
  if (m.window.size() >= kBestPolicyMinEpisodes) {
    double s = m.window.Means().success;
    if (s >= m.progress.best_success) {
      m.progress.best_success = s;
      SH_RETURN_IF_ERROR(m.WritePolicy(m.out + "/best_policy.pt"));
    }
  }
  m.last_ckpt = Clock::now();
  return absl::OkStatus();
}

core::StatusOr<IterationStats> PpoTrainer::Iterate() {
  Impl& m = *impl_;
  auto t0 = Clock::now();
  const core::CommStats comm0 = m.comm->stats();
  // env steps of all ranks
  const int64_t n = static_cast<int64_t>(m.cfg.rollout_steps) * m.env->num_envs() * m.comm->size();
  const float gamma = static_cast<float>(m.cfg.gamma);
  IterationStats st;
  // what every rank holds alike before its own rollout
  const control::ObsNormalizer norm_before = m.norm;
  const double episodes0 = static_cast<double>(m.progress.episodes), count0 = m.curr_count,
               success0 = m.curr_success;

  // rollout and advantages
  VecRolloutOptions ro;
  ro.steps = m.cfg.rollout_steps;
  ro.gamma = gamma;
  ro.chunks = m.cfg.rollout_chunks;
  RolloutBuffer rollout = CollectVecRollout(*m.env, m.net, m.norm, m.rng, m.amp.get(), ro,
                                            [&m](const EpisodeStats& e) { m.OnEpisode(e); });
  PpoBatch batch = rollout.Finish(gamma, static_cast<float>(m.cfg.lambda));
  const double own_rollout_s = std::chrono::duration<double>(Clock::now() - t0).count();
  if (m.comm->size() > 1) {
    // the ranks' rollouts: one normaliser, global episode counts (and so one curriculum)
    SH_RETURN_IF_ERROR(MergeNormalizer(norm_before, &m.norm, *m.comm));
    // (and, in one slot per rank, each rank's own rollout time: the spread the sync waits for)
    std::vector<double> counts{m.progress.episodes - episodes0, m.curr_count - count0,
                               m.curr_success - success0};
    counts.resize(3 + m.comm->size(), 0.0);
    counts[3 + m.rank()] = own_rollout_s;
    SH_RETURN_IF_ERROR(SumCounts(&counts, *m.comm));
    m.progress.episodes = static_cast<int64_t>(episodes0 + counts[0]);
    m.curr_count = static_cast<int>(count0 + counts[1]);
    m.curr_success = static_cast<int>(success0 + counts[2]);
    st.rank_rollout_s.assign(counts.begin() + 3, counts.end());
  }
  const core::CommStats comm1 = m.comm->stats();
  m.progress.env_steps += n;
  auto t1 = Clock::now();
  // the env threads are idle during the update: it gets the cores
  torch::set_num_threads(m.cfg.update_torch_threads);
  m.AdvanceCurriculum(n);

  // policy and value update, undone and counted when not finite
  const double lr = m.Lr();
  SetLearningRate(*m.net.opt, lr);
  m.guard.Begin(m.net.Params());
  PpoUpdateOptions update_options = m.UpdateOptions();
  update_options.comm = m.comm;
  PpoUpdateStats up = PpoUpdate(m.net, batch, update_options, m.rng);
  absl::Status guard = m.guard.End(up, m.progress.iteration);
  if (!guard.ok()) {
    torch::set_num_threads(m.cfg.torch_threads);
    return guard;
  }
  // discriminator: agent pairs of this rollout into the replay buffer, then a few updates
  if (m.amp) m.amp->Update(m.rng, &st);
  torch::set_num_threads(m.cfg.torch_threads);
  auto t2 = Clock::now();
  ++m.progress.iteration;
  double collect = std::chrono::duration<double>(t1 - t0).count();
  double update = std::chrono::duration<double>(t2 - t1).count();
  m.progress.wall_s += collect + update;

  m.FillStats(&st);
  st.policy_loss = up.policy_loss;
  st.value_loss = up.value_loss;
  st.entropy = up.entropy;
  st.approx_kl = up.approx_kl;
  st.clip_frac = up.clip_frac;
  st.skipped_minibatches = up.skipped;
  st.stepped_minibatches = up.minibatches;
  st.lr = lr;
  st.collect_s = collect;
  st.update_s = update;
  st.steps_per_s = static_cast<double>(n) / std::max(1e-9, collect + update);
  st.ranks = m.comm->size();
  st.sync_s = comm1.allreduce_s - comm0.allreduce_s;
  st.allreduce_calls = m.comm->stats().allreduce_calls - comm1.allreduce_calls;
  st.allreduce_bytes = m.comm->stats().allreduce_bytes - comm1.allreduce_bytes;
  st.allreduce_s = m.comm->stats().allreduce_s - comm1.allreduce_s;
  if (std::chrono::duration<double>(Clock::now() - m.last_ckpt).count() >=
          m.cfg.checkpoint_every_s ||
      done()) {
    SH_RETURN_IF_ERROR(Checkpoint());
    st.checkpointed = true;
  }
  if (m.rank() == 0) AppendJsonLine(m.out + "/log.jsonl", st.ToJson());
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
    return SaveArchiveAtomic(ar, out);
  } catch (const c10::Error& e) {
    return absl::InternalError(out + ": " + e.what_without_backtrace());
  }
}

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

core::StatusOr<std::unique_ptr<VecTask>> MakeVecTask(const std::string& name, int num_envs,
                                                     const std::string& physics_solver,
                                                     const std::string& walk_gait) {
  SH_RETURN_IF_ERROR(CheckWalkGaitTask(name, walk_gait));
  TaskOptions o;
  o.solver = physics_solver;
  o.walk_gait = walk_gait;
  return MakeTask(name, num_envs, o);
}

}  // namespace simhuman::learn
