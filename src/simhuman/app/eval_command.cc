#include "simhuman/app/eval_command.h"

#include <algorithm>
#include <cmath>
#include <cstdarg>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <optional>

#include "simhuman/app/carry_eval_command.h"
#include "simhuman/app/common.h"
#include "simhuman/app/planner_factory.h"
#include "simhuman/app/tabletop_eval_command.h"
#include "simhuman/app/vision_command.h"
#include "simhuman/eval/episode.h"
#include "simhuman/eval/eval_job.h"
#include "simhuman/eval/eval_runner.h"
#include "simhuman/eval/language_suite.h"
#include "simhuman/eval/walk_eval.h"

namespace simhuman::app {
namespace {

// stands for a boolean flag in the checks of string-valued flags: set (non-empty) or not
const std::string kFlagSet = "set", kFlagUnset;

const char kCommand[] = "eval";

std::string Row(const char* fmt, ...) __attribute__((format(printf, 1, 2)));
std::string Row(const char* fmt, ...) {
  char buf[512];
  va_list args;
  va_start(args, fmt);
  std::vsnprintf(buf, sizeof(buf), fmt, args);
  va_end(args);
  return buf;
}

std::string Cm(double m) {
  if (!(m >= 0) || !std::isfinite(m)) return "-";
  char buf[32];
  std::snprintf(buf, sizeof(buf), "%.1f", 100 * m);
  return buf;
}

std::string Extra(const eval::ExtraResult& e) {
  if (e.metric.empty()) return "-";
  char buf[48];
  if (e.metric == "hand_distance_m") {
    std::snprintf(buf, sizeof(buf), "hand %s cm %s", Cm(e.value).c_str(), e.pass ? "ok" : "FAIL");
  } else if (std::isfinite(e.value)) {
    std::snprintf(buf, sizeof(buf), "axis %.0f deg %s", e.value, e.pass ? "ok" : "FAIL");
  } else {
    std::snprintf(buf, sizeof(buf), "%s FAIL", e.metric.c_str());
  }
  return buf;
}

void PrintHeader(std::ostream& out) {
  out << Row("%4s %-24s %-4s %-6s %7s %-4s %-20s %6s %6s %-20s", "ep", "variant", "ok", "steps",
             "err_cm", "fell", "end", "sim_s", "w/sim", "extra")
      << std::endl;
}

void PrintEpisode(std::ostream& out, const eval::EpisodeRecord& r) {
  const control::EpisodeResult& res = r.result;
  std::string steps = std::to_string(res.steps_completed) + "/" + std::to_string(res.steps_total);
  std::string end =
      res.end_reason.size() > 20 ? res.end_reason.substr(0, 19) + "~" : res.end_reason;
  double wps = res.sim_time_s > 0 ? res.wall_time_s / res.sim_time_s : 0.0;
  out << Row("%4d %-24s %-4s %-6s %7s %-4s %-20s %6.2f %6.2f %-20s", r.index,
             r.variant.substr(0, 24).c_str(), r.success ? "yes" : "no", steps.c_str(),
             Cm(res.contact_error_m).c_str(), res.fell ? "yes" : "no", end.c_str(), res.sim_time_s,
             wps, Extra(r.extra).c_str())
      << std::endl;
  if (!r.render_error.empty()) {
    out << "     (contact sheet not written: " << r.render_error << ")" << std::endl;
  }
}

void PrintSummary(std::ostream& out, const eval::Summary& s) {
  out << "\nsummary\n";
  out << Row("%-18s %8s %8s %8s %10s %10s %10s %8s %8s %8s", "suite", "episodes", "success",
             "succ_jc", "err_cm", "err_jc_cm", "succ_steps", "falls", "extra", "w/sim")
      << "\n";
  std::string eps = std::to_string(s.episodes) + "/" + std::to_string(s.episodes_requested);
  std::string succ_jc = s.success_rate_unihsi_points
                            ? Row("%.1f%%", 100 * *s.success_rate_unihsi_points)
                            : std::string("-");
  out << Row("%-18s %8s %7.1f%% %8s %10s %10s %6.2f/%-3.2g %7.1f%% %7.1f%% %8.2f", s.suite.c_str(),
             eps.c_str(), 100 * s.success_rate, succ_jc.c_str(),
             s.contact_error_m ? Cm(*s.contact_error_m).c_str() : "-",
             s.contact_error_joint_centre_m ? Cm(*s.contact_error_joint_centre_m).c_str() : "-",
             s.success_steps, s.steps_total, 100 * s.fall_rate, 100 * s.extra_pass_rate,
             s.wall_per_sim)
      << std::endl;
  if (s.motion) {
    out << "human-norm motion metrics (docs/EVAL_PROTOCOLS.md):\n"
        << eval::MotionNormsReport(*s.motion) << std::flush;
  }
}

// the language suite: the command corpus through a planner
int LanguageEval(const EvalFlags& flags, std::ostream& out, std::ostream& err) {
  core::StatusOr<std::unique_ptr<language::Planner>> planner =
      MakePlanner(flags.planner, flags.llm);
  if (!planner.ok()) return ReportError(err, kCommand, planner.status());
  const std::string corpus =
      flags.corpus.empty() ? eval::DefaultLanguageCorpusPath() : flags.corpus;
  core::StatusOr<std::vector<eval::LanguageCase>> cases = eval::LoadLanguageCorpus(corpus);
  if (!cases.ok()) return ReportError(err, kCommand, cases.status());
  const std::string dir = flags.out.empty() ? "out/eval_language" : flags.out;
  absl::Status made = MakeOutputDir(dir);
  if (!made.ok()) return ReportError(err, kCommand, made);
  core::StatusOr<eval::LanguageSummary> s = eval::RunLanguageCorpus(
      *cases, std::filesystem::path(corpus).parent_path().string(), **planner);
  if (!s.ok()) return ReportError(err, kCommand, s.status());
  for (const eval::LanguageCaseResult& r : s->results) {
    if (r.pass) continue;
    out << "FAIL line " << r.c.line << " [" << r.c.scene << "] \"" << r.c.command << "\" -> "
        << r.got << std::endl;
  }
  out << Row("language suite (%s planner, %s)\n", flags.planner.c_str(), corpus.c_str());
  out << Row("  exact plans        %4d/%-4d %6.1f%%\n", s->plan_exact, s->plan_cases,
             100 * s->exact_rate());
  out << Row("  ambiguous refused  %4d/%-4d %6.1f%%\n", s->ambiguous_refused, s->ambiguous_cases,
             100 * s->refused_rate());
  out << Row("  errors reported    %4d/%-4d %6.1f%%\n", s->error_correct, s->error_cases,
             100 * s->error_rate());
  out << Row("  latency median %.1f us, p99 %.1f us, max %.1f us\n", s->median_latency_us,
             s->p99_latency_us, s->max_latency_us);
  const std::string path = (std::filesystem::path(dir) / "summary.json").string();
  absl::Status st = eval::WriteJsonFile(path, eval::LanguageSummaryJson(*s, flags.planner, corpus));
  if (!st.ok()) return ReportError(err, kCommand, absl::InternalError(st.message()));
  out << "wrote " << path << std::endl;
  return 0;
}

// the `walk` and `walk-step` suites: the walking policy alone (eval/walk_eval.h)
// one run of a walk suite at `o.scale`; writes its files under o.sheet_dir
int WalkEvalOnce(const EvalFlags& flags, eval::WalkEvalOptions o, std::ostream& out,
                 std::ostream& err, eval::WalkEvalSummary* result) {
  absl::Status dir = MakeOutputDir(o.sheet_dir);
  if (!dir.ok()) return ReportError(err, kCommand, dir);
  std::ofstream lines(o.sheet_dir + "/episodes.jsonl", std::ios::trunc);
  out << "simhuman eval: suite " << flags.suite << ", " << o.episodes << " episodes, seed "
      << o.seed << ", scale " << o.scale << ", policy " << o.policy << " -> " << o.sheet_dir
      << std::endl;
  out << Row("%4s %7s %8s %-4s %-4s %7s %8s %8s %9s %9s %8s %7s", "ep", "dist_m", "bear_deg", "ok",
             "fell", "time_s", "end_cm", "end_deg", "speed_ms", "skate_ms", "turn_deg", "arm_deg")
      << std::endl;
  auto summary = eval::RunWalkEval(o, nullptr, [&](const eval::WalkEpisode& e) {
    out << Row("%4d %7.2f %8.0f %-4s %-4s %7.2f %8.1f %8.1f %9.2f %9.3f %8.0f %7.0f", e.index,
               e.dist_m, e.bearing_deg, e.success ? "yes" : "no", e.fell ? "yes" : "no", e.time_s,
               100 * e.final_dist_m, e.final_yaw_err_deg, e.mean_speed_mps, e.foot_skate_mps,
               e.max_turn_deg, e.arm_raise_deg)
        << std::endl;
    if (!e.render_error.empty())
      out << "     (not rendered: " << e.render_error << ")" << std::endl;
    lines << eval::WalkEpisodeJson(e).dump() << "\n" << std::flush;
  });
  if (!summary.ok()) return ReportError(err, kCommand, summary.status());
  absl::Status ws =
      eval::WriteJsonFile(o.sheet_dir + "/summary.json", eval::WalkSummaryJson(*summary, o));
  if (!ws.ok()) return ReportError(err, kCommand, ws);
  out << Row("\nsummary: success %.1f%%  falls %.1f%%  time %.1f s  skate %.3f m/s  end %.1f cm "
             "%.1f deg  turn %.0f deg (no turn >= 45 deg: %.0f%% of successes)  arm raised "
             "%.0f deg",
             100 * summary->success_rate, 100 * summary->fall_rate, summary->mean_time_s,
             summary->foot_skate_mps, 100 * summary->final_dist_m, summary->final_yaw_err_deg,
             summary->max_turn_deg, 100 * summary->no_turn_rate, summary->arm_raise_deg)
      << std::endl;
  out << "human-norm gait metrics (steady walking only; docs/EVAL_PROTOCOLS.md):\n"
      << eval::MotionNormsReport(summary->motion) << std::flush;
  *result = *summary;
  return kExitOk;
}

int WalkEvalCommand(const EvalFlags& flags, std::ostream& out, std::ostream& err) {
  if (flags.policy.empty()) {
    return ReportError(
        err, kCommand,
        absl::InvalidArgumentError("--suite " + flags.suite + " needs --policy <file>"));
  }
  if (flags.physics_solver != "newton" && flags.physics_solver != "pgs") {
    return ReportError(err, kCommand,
                       absl::InvalidArgumentError("--physics-solver '" + flags.physics_solver +
                                                  "' is unknown; valid: newton, pgs"));
  }
  eval::WalkEvalOptions o;
  o.step_suite = flags.suite == "walk-step";
  o.physics_solver = flags.physics_solver;
  o.policy = flags.policy;
  o.episodes = flags.episodes;
  o.seed = flags.seed;
  o.video_every = flags.video_every;
  o.video = flags.video;
  o.sheet_dir = flags.out.empty() ? "out/eval_" + flags.suite : flags.out;
  for (double sc : flags.scales) {
    if (!(sc >= 0.5 && sc <= 1.5)) {
      return ReportError(err, kCommand,
                         absl::InvalidArgumentError("--scales entry " + Row("%g", sc) +
                                                    " is invalid; valid: a scale in [0.5, 1.5]"));
    }
  }
  if (flags.scales.size() <= 1) {
    o.scale = flags.scales.empty() ? 1.0 : flags.scales[0];
    eval::WalkEvalSummary s;
    return WalkEvalOnce(flags, o, out, err, &s);
  }
  // one run per scale, each in its own folder, then success per scale
  const std::string base = o.sheet_dir;
  std::vector<std::pair<double, eval::WalkEvalSummary>> rows;
  for (double sc : flags.scales) {
    o.scale = sc;
    o.sheet_dir = base + "/scale_" + Row("%.2f", sc);
    eval::WalkEvalSummary s;
    int rc = WalkEvalOnce(flags, o, out, err, &s);
    if (rc != kExitOk) return rc;
    rows.emplace_back(sc, s);
  }
  out << "\nper scale (" << flags.suite << ", " << o.episodes << " episodes each)\n"
      << Row("%6s %8s %7s %7s %9s", "scale", "success", "falls", "time_s", "skate_ms") << "\n";
  for (const auto& [sc, s] : rows) {
    out << Row("%6.2f %7.1f%% %6.1f%% %7.1f %9.3f", sc, 100 * s.success_rate, 100 * s.fall_rate,
               s.mean_time_s, s.foot_skate_mps)
        << "\n";
  }
  out << std::flush;
  return kExitOk;
}

// "3, 5, 7" (at most the first 20)
std::string IndexList(const std::vector<int>& v) {
  std::string s;
  for (size_t i = 0; i < v.size() && i < 20; ++i) s += (i ? ", " : "") + std::to_string(v[i]);
  if (v.size() > 20) s += ", ... (" + std::to_string(v.size()) + " in all)";
  return s;
}

// the plan suites' options from the flags
core::StatusOr<eval::EvalOptions> PlanSuiteOptions(const EvalFlags& flags,
                                                   const eval::SuiteDef& suite) {
  if (flags.episodes < 1) {
    return absl::InvalidArgumentError("--episodes " + std::to_string(flags.episodes) +
                                      " is invalid; valid: an integer >= 1");
  }
  if (flags.video_every < 0) {
    return absl::InvalidArgumentError(
        "--video-every " + std::to_string(flags.video_every) +
        " is invalid; valid: 0 (none) or K >= 1 (every K-th episode)");
  }
  if (!flags.scales.empty()) {
    const auto& ok = eval::ScalableSuites();
    if (std::find(ok.begin(), ok.end(), suite.name) == ok.end()) {
      return absl::InvalidArgumentError("--scales does not apply to --suite " + suite.name +
                                        "; valid: the walk suites and " + core::JoinNames(ok));
    }
    for (double sc : flags.scales) {
      if (!(sc >= 0.5 && sc <= 1.5)) {
        return absl::InvalidArgumentError("--scales entry " + Row("%g", sc) +
                                          " is invalid; valid: a scale in [0.5, 1.5]");
      }
    }
  }
  SH_ASSIGN_OR_RETURN(control::MpcConfig config,
                      ResolveConfig(flags.preset, flags.preset_given, flags.config));
  eval::EvalOptions options;
  options.suite = suite.name;
  options.episodes = flags.episodes;
  options.seed = flags.seed;
  options.out_dir = flags.out.empty() ? "out/eval_" + flags.suite : flags.out;
  options.config = config;
  options.video_every = flags.video_every;
  options.walk_policy = eval::DefaultWalkPolicy(flags.policy);
  options.resume = flags.resume;
  return options;
}

// one run of a plan suite with `options` (every rank); its summary in *summary
int PlanSuiteOnce(const EvalFlags& flags, const eval::EvalOptions& options, std::ostream& out,
                  std::ostream& err, core::Communicator& comm, eval::Summary* result) {
  out << "simhuman eval: suite " << flags.suite << ", " << flags.episodes << " episodes, seed "
      << flags.seed << ", preset " << options.config.preset;
  if (options.human_scale != 1.0) out << ", human scale " << options.human_scale;
  out << " -> " << options.out_dir;
  if (comm.size() > 1) out << ", " << comm.size() << " ranks (" << comm.name() << ")";
  out << std::endl;
  eval::EvalHooks hooks;
  hooks.on_start = [&](const eval::EvalStart& s) {
    if (options.resume) {
      out << "resuming: " << s.finished.size() << " of " << options.episodes
          << " episodes finished; missing (to run now): "
          << (s.to_run.empty() ? std::string("none") : IndexList(s.to_run)) << std::endl;
    }
    PrintHeader(out);
  };
  hooks.on_episode = [&](const eval::EpisodeRecord& r, const eval::Summary&) {
    PrintEpisode(out, r);
  };
  core::StatusOr<eval::Summary> summary = eval::RunEval(options, hooks, comm);
  if (!summary.ok()) {
    int code = ReportError(err, kCommand, summary.status());
    return code == kExitOk ? kExitInternal : code;
  }
  PrintSummary(out, *summary);
  out << "wrote " << (std::filesystem::path(options.out_dir) / "summary.json").string() << " and "
      << (std::filesystem::path(options.out_dir) / "episodes.jsonl").string() << std::endl;
  *result = *summary;
  return kExitOk;
}

}  // namespace

int EvalCommand(const EvalFlags& flags, std::ostream& out, std::ostream& err,
                core::Communicator& comm) {
  const eval::SuiteDef* suite = eval::FindSuite(flags.suite);
  if (!suite) {
    return ReportError(
        err, kCommand,
        absl::InvalidArgumentError("--suite: unknown suite '" + flags.suite +
                                   "'; valid suites are: " + core::JoinNames(eval::SuiteNames())));
  }
  if (suite->controller != eval::SuiteController::kMpc && (comm.size() > 1 || flags.resume)) {
    return ReportError(err, kCommand,
                       absl::InvalidArgumentError(
                           "--suite " + flags.suite +
                           " runs in one process without --resume; mpirun and --resume work "
                           "with the plan suites (sit, lie, reach, sceneplan-simple, ...)"));
  }
  if (!flags.scales.empty() && suite->controller != eval::SuiteController::kWalkPolicy &&
      suite->controller != eval::SuiteController::kMpc) {
    return ReportError(err, kCommand,
                       absl::InvalidArgumentError("--scales does not apply to --suite " +
                                                  flags.suite + "; valid: the walk suites and " +
                                                  core::JoinNames(eval::ScalableSuites())));
  }
  // flags of the tabletop suites alone: {set, the flag(s), what the other suites have instead}
  const struct {
    bool set;
    const char* flag;
    const char* instead;
  } tabletop_only[] = {
      {flags.jobs > 1, "--jobs applies", "; the plan suites run in parallel with mpirun -n N"},
      {flags.first_episode != 0, "--first-episode applies",
       "; the plan suites continue a run with --resume"},
      {flags.place_policy != "scripted", "--place-policy applies", ""},
      {!flags.zero_shot.empty() || !flags.zero_shot_mesh.empty(),
       "--zero-shot and --zero-shot-mesh apply", ""},
      {flags.planner_seed != 1, "--planner-seed applies", ""},
      {flags.no_touch, "--no-touch applies", ""},
  };
  for (const auto& f : tabletop_only) {
    if (!f.set || suite->controller == eval::SuiteController::kTabletop) continue;
    return ReportError(err, kCommand,
                       absl::InvalidArgumentError(std::string(f.flag) +
                                                  " to the tabletop suites (tabletop, place, "
                                                  "stack), not --suite " +
                                                  flags.suite + f.instead));
  }
  for (const auto& [flag, value] :
       {std::pair<const char*, const std::string*>{"--approach-policy", &flags.approach_policy},
        {"--walker", &flags.walker},
        {"--lift-policy", &flags.lift_policy},
        {"--deliver-policy", &flags.deliver_policy},
        {"--model-squats", flags.model_squats ? &kFlagSet : &kFlagUnset}}) {
    if (value->empty() || suite->controller == eval::SuiteController::kCarryPolicy) continue;
    return ReportError(
        err, kCommand,
        absl::InvalidArgumentError(std::string(flag) + " applies to --suite carry, not --suite " +
                                   flags.suite));
  }
  if (flags.no_silhouette && suite->controller != eval::SuiteController::kTabletop &&
      suite->controller != eval::SuiteController::kVision) {
    return ReportError(err, kCommand,
                       absl::InvalidArgumentError(
                           "--no-silhouette applies to --suite vision and the tabletop suites "
                           "(tabletop, place, stack), not --suite " +
                           flags.suite));
  }
  if (suite->controller == eval::SuiteController::kPlanner) return LanguageEval(flags, out, err);
  if (suite->controller == eval::SuiteController::kCarryPolicy) {
    return CarryEvalCommand(flags, out, err);
  }
  if (suite->controller == eval::SuiteController::kTabletop) {
    return TabletopEvalCommand(flags, out, err);
  }
  if (suite->controller == eval::SuiteController::kVision)
    return VisionEvalCommand(flags, out, err);
  if (suite->controller == eval::SuiteController::kWalkPolicy) {
    if (flags.episodes < 1) {
      return ReportError(err, kCommand, absl::InvalidArgumentError("--episodes must be >= 1"));
    }
    return WalkEvalCommand(flags, out, err);
  }
  // every rank checks its own flags and files; all stop if one fails
  core::StatusOr<eval::EvalOptions> opts = PlanSuiteOptions(flags, *suite);
  absl::Status agreed = core::AgreeOk(comm, opts.status());
  if (!agreed.ok()) return ReportError(err, kCommand, agreed);
  eval::EvalOptions options = *opts;
  if (flags.scales.empty()) {
    eval::Summary s;
    return PlanSuiteOnce(flags, options, out, err, comm, &s);
  }
  // --scales: one run per body size, each in its own folder, then success per scale
  const std::string base = options.out_dir;
  std::vector<std::pair<double, eval::Summary>> rows;
  for (double sc : flags.scales) {
    options.human_scale = sc;
    options.out_dir = flags.scales.size() == 1 ? base : base + "/scale_" + Row("%.2f", sc);
    eval::Summary s;
    int rc = PlanSuiteOnce(flags, options, out, err, comm, &s);
    if (rc != kExitOk) return rc;
    rows.emplace_back(sc, s);
  }
  if (rows.size() > 1) {
    out << "\nper scale (" << flags.suite << ", " << flags.episodes << " episodes each)\n"
        << Row("%6s %8s %7s %8s", "scale", "success", "falls", "err_cm") << "\n";
    for (const auto& [sc, s] : rows) {
      out << Row("%6.2f %7.1f%% %6.1f%% %8s", sc, 100 * s.success_rate, 100 * s.fall_rate,
                 s.contact_error_m ? Cm(*s.contact_error_m).c_str() : "-")
          << "\n";
    }
    out << std::flush;
  }
  return kExitOk;
}

}  // namespace simhuman::app
