#include "simhuman/app/train_command.h"

#include <atomic>
#include <chrono>
#include <cmath>
#include <csignal>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <sstream>
#include <vector>

#include "simhuman/app/common.h"
#include "simhuman/app/vision_command.h"
#include "simhuman/core/json_io.h"
#include "simhuman/core/version.h"
#include "simhuman/learn/ppo.h"

namespace simhuman::app {
namespace {

// Ctrl-C / SIGTERM: finish the iteration, write the checkpoint, then stop
std::atomic<int> g_stop_signal{0};
extern "C" void OnStopSignal(int sig) { g_stop_signal.store(sig); }

// installs the handlers for the life of one train command, restoring the old ones after
class StopSignals {
 public:
  StopSignals() {
    g_stop_signal.store(0);
    old_int_ = std::signal(SIGINT, OnStopSignal);
    old_term_ = std::signal(SIGTERM, OnStopSignal);
  }
  ~StopSignals() {
    std::signal(SIGINT, old_int_);
    std::signal(SIGTERM, old_term_);
  }
  StopSignals(const StopSignals&) = delete;
  StopSignals& operator=(const StopSignals&) = delete;

 private:
  void (*old_int_)(int) = SIG_DFL;
  void (*old_term_)(int) = SIG_DFL;
};

std::string Duration(double s) {
  if (!std::isfinite(s) || s < 0) return "--:--";
  long t = static_cast<long>(s);
  char buf[32];
  std::snprintf(buf, sizeof(buf), "%ld:%02ld:%02ld", t / 3600, (t / 60) % 60, t % 60);
  return buf;
}

std::string Bar(double frac, int width) {
  int n = static_cast<int>(std::round(std::clamp(frac, 0.0, 1.0) * width));
  return std::string(n, '#') + std::string(width - n, '.');
}

}  // namespace

absl::Status ParseStepCount(const std::string& text, int64_t* out) {
  std::string t = text;
  double mult = 1;
  if (!t.empty()) {
    char c = t.back();
    if (c == 'k' || c == 'K') mult = 1e3;
    if (c == 'm' || c == 'M') mult = 1e6;
    if (c == 'g' || c == 'G') mult = 1e9;
    if (mult != 1) t.pop_back();
  }
  char* end = nullptr;
  double v = t.empty() ? NAN : std::strtod(t.c_str(), &end);
  if (t.empty() || end != t.c_str() + t.size() || !std::isfinite(v) || v * mult < 1 ||
      v * mult > 1e12) {
    return absl::InvalidArgumentError("--steps '" + text +
                                      "' is invalid; valid: a positive count such as 30M, 500k");
  }
  *out = static_cast<int64_t>(v * mult);
  return absl::OkStatus();
}

// `train --resume`: the run's own settings, with --config's schedule keys changed
core::StatusOr<std::unique_ptr<learn::PpoTrainer>> ResumeTrainer(const TrainFlags& flags,
                                                                 int64_t steps,
                                                                 core::Communicator& comm) {
  if (!flags.out.empty() || flags.seed_given || flags.envs || flags.threads ||
      !flags.amp_clips.empty() || !flags.init_from.empty()) {
    return absl::InvalidArgumentError(
        "--resume continues a run with its own settings; only --steps and --config (its "
        "schedule keys) may be given");
  }
  nlohmann::json changes = nlohmann::json::object();
  if (!flags.config.empty()) {
    SH_ASSIGN_OR_RETURN(changes, core::ReadJsonFile(flags.config));
  }
  auto trainer =
      learn::PpoTrainer::Resume(flags.resume, flags.steps_given ? steps : 0, &comm, changes);
  if (!trainer.ok() && !flags.config.empty()) return core::Annotate(trainer.status(), flags.config);
  return trainer;
}

int TrainCommand(const TrainFlags& flags, std::ostream& out, std::ostream& err,
                 core::Communicator& comm) {
  if (flags.task == "vision") return VisionTrainCommand(flags, out, err);
  int64_t steps = 0;
  if (flags.steps_given || flags.resume.empty()) {
    absl::Status s = ParseStepCount(flags.steps, &steps);
    if (!s.ok()) return ReportError(err, "train", s);
  }
  core::StatusOr<std::unique_ptr<learn::PpoTrainer>> trainer;
  if (!flags.resume.empty()) {
    trainer = ResumeTrainer(flags, steps, comm);
  } else {
    if (flags.out.empty()) {
      return ReportError(err, "train",
                         absl::InvalidArgumentError("--out (or --resume) is required"));
    }
    learn::PpoConfig cfg;
    bool config_names_task = false;
    if (!flags.config.empty()) {
      std::ifstream f(flags.config);
      if (!f) return ReportError(err, "train", absl::NotFoundError(flags.config + ": cannot open"));
      nlohmann::json j = nlohmann::json::parse(f, nullptr, false);
      if (j.is_discarded()) {
        return ReportError(err, "train", absl::InvalidArgumentError(flags.config + ": not JSON"));
      }
      auto c = learn::PpoConfig::FromJson(j);
      if (!c.ok()) return ReportError(err, "train", core::Annotate(c.status(), flags.config));
      cfg = *c;
      config_names_task = j.contains("task");
    }
    // --task wins; without it, the config's task (a grasp config trains grasping, not walking)
    if (flags.task_given || !config_names_task) cfg.task = flags.task;
    cfg.total_steps = steps;
    if (flags.seed_given || flags.config.empty()) cfg.seed = flags.seed;
    if (flags.envs) cfg.num_envs = flags.envs;
    if (flags.threads) cfg.threads = flags.threads;
    if (cfg.task == "reach") cfg.hidden = {64, 64};
    if (!flags.amp_clips.empty()) {
      cfg.amp_clips.clear();
      std::stringstream list(flags.amp_clips);
      std::string item;
      while (std::getline(list, item, ',')) {
        if (item.empty()) {
          return ReportError(err, "train",
                             absl::InvalidArgumentError("--amp-clips '" + flags.amp_clips +
                                                        "' holds an empty path"));
        }
        cfg.amp_clips.push_back(item);
      }
    }
    if (!flags.init_from.empty()) cfg.init_from = flags.init_from;
    // paths are stored absolute, so the run's config names them from any directory
    auto absolute = [](std::string& c) {
      std::error_code ec;
      std::filesystem::path abs = std::filesystem::absolute(c, ec);
      if (!ec) c = abs.lexically_normal().string();
    };
    for (std::string& c : cfg.amp_clips) absolute(c);
    if (!cfg.init_from.empty()) absolute(cfg.init_from);
    trainer = learn::PpoTrainer::Create(cfg, flags.out, &comm);
  }
  // every rank started, from the same config and checkpoint, or all stop
  absl::Status agreed = core::AgreeOk(comm, trainer.status());
  if (agreed.ok()) {
    const learn::PpoTrainer& t = **trainer;
    agreed = core::CheckSameOnAllRanks(
        comm, "training config and run folder",
        t.config().ToJson().dump() + t.out_dir() + std::to_string(t.env_steps()));
  }
  if (!agreed.ok()) return ReportError(err, "train", agreed);
  learn::PpoTrainer& tr = **trainer;
  const learn::PpoConfig& cfg = tr.config();
  out << "simhuman train: task " << cfg.task << ", " << cfg.num_envs << " envs, " << cfg.threads
      << " threads"
      << (comm.size() > 1 ? " per rank x " + std::to_string(comm.size()) + " ranks (" +
                                comm.name() + ", data-parallel)"
                          : std::string())
      << ", seed " << cfg.seed << ", target " << cfg.total_steps << " steps, run " << tr.out_dir()
      << (flags.resume.empty() ? "" : " (resumed at " + std::to_string(tr.env_steps()) + ")")
      << (cfg.amp_clips.empty() ? ""
                                : ", AMP with " + std::to_string(cfg.amp_clips.size()) + " clip(s)")
      << std::endl;
  auto start = std::chrono::steady_clock::now();
  int64_t start_steps = tr.env_steps();
  StopSignals signals;
  while (!tr.done()) {
    // a signal to any rank stops all of them at the same iteration
    std::vector<double> stop{static_cast<double>(g_stop_signal.load())};
    absl::Status stop_st = comm.size() > 1 ? comm.AllreduceSum(stop.data(), 1) : absl::OkStatus();
    if (!stop_st.ok()) return ReportError(err, "train", stop_st);
    if (stop[0] > 0) {
      const int sig = g_stop_signal.load() ? g_stop_signal.load() : SIGTERM;
      absl::Status s = tr.Checkpoint();
      if (!s.ok()) return ReportError(err, "train", s);
      out << "\nsimhuman train: stopped by signal " << sig << " at " << tr.env_steps()
          << " steps; checkpoint in " << tr.out_dir() << "; continue with: simhuman train "
          << "--resume " << tr.out_dir() << std::endl;
      return 128 + sig;
    }
    auto st = tr.Iterate();
    absl::Status iter_st = core::AgreeOk(comm, st.status());
    if (!iter_st.ok()) {
      (void)tr.Checkpoint();
      return ReportError(err, "train", iter_st);
    }
    double el = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    double rate = (st->env_steps - start_steps) / std::max(1e-9, el);
    double eta = (cfg.total_steps - st->env_steps) / std::max(1e-9, rate);
    if (!flags.quiet) {
      std::ostringstream line;
      line << "\r[" << Bar(static_cast<double>(st->env_steps) / cfg.total_steps, 30) << "] "
           << std::fixed << std::setprecision(2) << st->env_steps / 1e6 << "M/"
           << cfg.total_steps / 1e6 << "M  " << std::setprecision(0) << rate << " st/s  ret "
           << std::setprecision(2) << st->mean_return << "  succ " << st->success_rate << "  fall "
           << st->fall_rate << "  cur " << st->curriculum;
      if (st->ranks > 1) {
        line << "  allreduce " << std::setprecision(1)
             << 100 * st->allreduce_s / std::max(1e-9, st->collect_s + st->update_s) << "%";
      }
      if (st->amp) {
        line << "  style " << st->amp_style_reward << "  D " << st->amp_d_expert << "/"
             << st->amp_d_agent;
      }
      line << "  ETA " << Duration(eta) << (st->checkpointed ? "  [ckpt]" : "       ");
      out << line.str() << std::flush;
      if (st->iteration % 50 == 0) out << std::endl;
    }
  }
  absl::Status s = tr.Checkpoint();
  if (!s.ok()) return ReportError(err, "train", s);
  out << "\nsimhuman train: done, " << tr.env_steps() << " steps; checkpoint in " << tr.out_dir()
      << std::endl;
  return kExitOk;
}

int ExportPolicyCommand(const std::string& checkpoint, const std::string& out_path,
                        const std::string& eval_summary, std::ostream& out, std::ostream& err) {
  absl::Status s = learn::ExportPolicy(checkpoint, out_path);
  if (!s.ok()) return ReportError(err, "export-policy", s);
  namespace fs = std::filesystem;
  fs::path run = fs::path(checkpoint).parent_path();
  auto read_json = [](const fs::path& p) {
    std::ifstream f(p);
    return f ? nlohmann::json::parse(f, nullptr, false) : nlohmann::json();
  };
  nlohmann::ordered_json prov;
  prov["policy"] = fs::path(out_path).filename().string();
  prov["source_checkpoint"] = checkpoint;
  prov["git_revision"] = std::string(core::GitRevision());
  nlohmann::json cfg = read_json(run / "config.json");
  prov["train_config"] = cfg;
  if (cfg.is_object()) {
    prov["command"] = "simhuman train --task " + cfg.value("task", std::string("?")) + " --steps " +
                      std::to_string(cfg.value("total_steps", int64_t{0})) +
                      " --out <run> --seed " + std::to_string(cfg.value("seed", uint64_t{0})) +
                      " --envs " + std::to_string(cfg.value("num_envs", 0)) + " --threads " +
                      std::to_string(cfg.value("threads", 0)) + "  (resumed with --resume <run>)";
  }
  // the log line of the checkpoint's step count
  auto meta = learn::ReadCheckpointProgress(checkpoint);
  if (meta.ok()) {
    prov["env_steps"] = meta->first;
    prov["train_wall_s"] = meta->second;
  }
  std::ifstream log(run / "log.jsonl");
  std::string line, last;
  while (std::getline(log, line)) {
    nlohmann::json j = nlohmann::json::parse(line, nullptr, false);
    if (j.is_object() && meta.ok() && j.value("env_steps", int64_t{0}) <= meta->first) last = line;
  }
  if (!last.empty()) prov["train_metrics"] = nlohmann::json::parse(last);
  if (!eval_summary.empty()) {
    nlohmann::json e = read_json(eval_summary);
    if (e.is_discarded() || e.is_null()) {
      return ReportError(err, "export-policy",
                         absl::InvalidArgumentError(eval_summary + ": cannot read the summary"));
    }
    prov["eval"] = e;
  }
  fs::path prov_path = fs::path(out_path).replace_extension(".json");
  std::ofstream(prov_path) << prov.dump(2) << "\n";
  out << "simhuman export-policy: wrote " << out_path << " and " << prov_path.string() << std::endl;
  return kExitOk;
}

}  // namespace simhuman::app
