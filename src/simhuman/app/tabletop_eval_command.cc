#include "simhuman/app/tabletop_eval_command.h"

#include <cstdio>
#include <filesystem>
#include <fstream>

#include "simhuman/app/common.h"
#include "simhuman/app/vision_command.h"
#include "simhuman/control/policy/place_policy.h"
#include "simhuman/eval/episode.h"
#include "simhuman/eval/tabletop_eval.h"

namespace simhuman::app {
namespace {

const char kCommand[] = "eval";

std::string Line(const eval::TabletopEpisode& e) {
  char buf[240];
  std::snprintf(buf, sizeof(buf), "%4d %-6s %-13s %-9s %-4s %-10s %7d %6.2f  %s", e.index,
                e.kind.c_str(), e.object.c_str(), e.shape.c_str(), e.success ? "yes" : "no",
                e.failed_stage.c_str(), e.sim_steps, e.wall_s, e.end_reason.c_str());
  return buf;
}

}  // namespace

int TabletopEvalCommand(const EvalFlags& flags, std::ostream& out, std::ostream& err) {
  eval::TabletopEvalOptions o;
  o.kind = flags.suite == "tabletop" ? "any" : flags.suite;
  o.episodes = flags.episodes;
  o.first_episode = flags.first_episode;
  o.seed = flags.seed;
  o.grasp = eval::DefaultGraspPolicy(flags.grasp_policy);
  o.place = flags.place_policy;
  o.perception = flags.perception;
  o.touch = !flags.no_touch;
  if (flags.no_touch && o.perception != "vision") {
    return ReportError(err, kCommand,
                       absl::InvalidArgumentError(
                           "--no-touch needs --perception vision (with truth the controllers "
                           "read the objects' true state and touch adds nothing)"));
  }
  o.silhouette = !flags.no_silhouette;
  if (flags.no_silhouette && o.perception != "vision") {
    return ReportError(
        err, kCommand,
        absl::InvalidArgumentError("--no-silhouette needs --perception vision (with truth the task "
                                   "planner reads the objects' true state)"));
  }
  o.grasp_attempts = flags.grasp_attempts;
  o.planner_seed = static_cast<uint64_t>(flags.planner_seed);
  o.zero_shot = flags.zero_shot;
  if (!flags.zero_shot_mesh.empty()) o.zero_shot_mesh = flags.zero_shot_mesh;
  if (!o.zero_shot.empty() && o.perception == "vision") {
    return ReportError(err, kCommand,
                       absl::InvalidArgumentError(
                           "--zero-shot runs with --perception truth only: the vision model "
                           "knows boxes, cylinders and spheres (DASH's zero-shot tests, too, "
                           "read the object's true pose)"));
  }
  if (o.zero_shot != "mesh" && !flags.zero_shot_mesh.empty()) {
    return ReportError(err, kCommand,
                       absl::InvalidArgumentError("--zero-shot-mesh needs --zero-shot mesh"));
  }
  o.jobs = flags.jobs;
  o.vision_model = flags.vision_model.empty() ? DefaultVisionModel() : flags.vision_model;
  if (o.perception == "vision") {
    if (absl::Status s = CheckVisionModelFile(o.vision_model); !s.ok()) {
      return ReportError(err, kCommand, s);
    }
  }
  if (absl::Status s = control::LoadPlacePolicy(o.place).status(); !s.ok()) {
    return ReportError(err, kCommand, s);
  }
  const std::string dir = flags.out.empty() ? "out/eval_" + flags.suite : flags.out;
  absl::Status made = MakeOutputDir(dir);
  if (!made.ok()) return ReportError(err, kCommand, made);
  std::ofstream lines(dir + "/episodes.jsonl", std::ios::trunc);
  out << "simhuman eval: suite " << flags.suite << ", " << o.episodes << " episodes"
      << (o.first_episode > 0 ? " from episode " + std::to_string(o.first_episode) : "")
      << ", seed " << o.seed << ", grasp " << o.grasp << " (" << o.grasp_attempts
      << " attempts), planner seed " << o.planner_seed << ", place " << o.place << ", perception "
      << o.perception
      << (o.perception == "vision"
              ? " (" + o.vision_model + (o.touch ? ", with touch" : ", without touch") +
                    (o.silhouette ? "" : ", without the silhouette fit") + ")"
              : std::string())
      << (o.zero_shot.empty() ? std::string()
                              : ", zero-shot " + o.zero_shot +
                                    (o.zero_shot == "mesh" ? " (" + o.zero_shot_mesh + ")" : ""))
      << " -> " << dir << std::endl;
  out << "  ep kind   object        shape     ok   failed at    steps wall_s  end" << std::endl;
  core::StatusOr<eval::TabletopEvalSummary> s =
      eval::RunTabletopEval(o, [&](const eval::TabletopEpisode& e) {
        out << Line(e) << std::endl;
        lines << eval::TabletopEpisodeJson(e).dump() << "\n" << std::flush;
      });
  if (!s.ok()) return ReportError(err, kCommand, s.status());
  nlohmann::ordered_json summary = s->ToJson();
  summary["suite"] = flags.suite;
  summary["seed"] = o.seed;
  summary["first_episode"] = o.first_episode;
  summary["grasp"] = o.grasp;
  summary["place"] = o.place;
  summary["grasp_attempts"] = o.grasp_attempts;
  summary["planner_seed"] = o.planner_seed;
  if (!o.zero_shot.empty()) summary["zero_shot"] = o.zero_shot;
  if (o.zero_shot == "mesh") summary["zero_shot_mesh"] = o.zero_shot_mesh;
  if (o.perception == "vision") summary["vision_model"] = o.vision_model;
  const nlohmann::ordered_json provenance = eval::ProvenanceJson();
  for (const auto& [key, value] : provenance.items()) summary[key] = value;
  absl::Status ws = eval::WriteJsonFile(dir + "/summary.json", summary);
  if (!ws.ok()) return ReportError(err, kCommand, ws);
  char buf[300];
  std::snprintf(buf, sizeof(buf),
                "\nsummary: success %.1f%% of all trials, %.1f%% excluding motion-planning "
                "failures (%d of %d)\npipeline %.0f simulation steps/s, raw mj_step %.0f "
                "(ratio %.2f)",
                100 * s->success_rate, 100 * s->success_rate_no_plan_fail, s->plan_failures,
                s->episodes, s->steps_per_s, s->raw_steps_per_s,
                s->raw_steps_per_s > 0 ? s->steps_per_s / s->raw_steps_per_s : 0.0);
  out << buf << std::endl;
  std::snprintf(buf, sizeof(buf),
                "per CPU second: pipeline %.0f steps, raw mj_step %.0f (ratio %.2f)",
                s->cpu_steps_per_s, s->raw_cpu_steps_per_s,
                s->raw_cpu_steps_per_s > 0 ? s->cpu_steps_per_s / s->raw_cpu_steps_per_s : 0.0);
  out << buf << std::endl;
  std::snprintf(buf, sizeof(buf), "simulated %.1f s in %.1f s of wall time (%.2fx real time)",
                s->sim_s, s->wall_s, s->wall_s > 0 ? s->sim_s / s->wall_s : 0.0);
  out << buf << std::endl;
  std::snprintf(buf, sizeof(buf),
                "the run: %d episodes at once, %.1f s elapsed, pipeline %.0f simulation steps/s "
                "in all",
                s->jobs, s->elapsed_s, s->steps_per_elapsed_s);
  out << buf << std::endl;
  if (o.perception == "vision") {
    std::snprintf(buf, sizeof(buf),
                  "vision: %d frames, %.2f ms inference + %.2f ms rendering per frame; %d "
                  "perception failures",
                  s->vision_frames, s->vision_ms_per_frame, s->render_ms_per_frame,
                  s->perception_failures);
    out << buf << std::endl;
  }
  for (const auto& [stage, n] : s->failures_by_stage) {
    out << "  failed at " << stage << ": " << n << std::endl;
  }
  out << "  grasped again after a miss: " << s->regrasped << " episodes, " << s->regrasped_successes
      << " of them succeeded" << std::endl;
  for (const auto& [task, t] : s->by_task) {
    out << "  " << task << ": " << t.successes << "/" << t.episodes << " (" << t.plan_failures
        << " plan failures)" << std::endl;
  }
  for (const char* kind : {"place", "stack"}) {
    const eval::TabletopEvalSummary::Tally t = s->DashTally(kind);
    if (t.episodes == 0) continue;
    std::snprintf(
        buf, sizeof(buf),
        "DASH's protocol (a box or cylinder moved), %s: %.1f%% of %d, %.1f%% excluding "
        "motion-planning failures",
        kind, 100.0 * t.successes / t.episodes, t.episodes,
        t.episodes > t.plan_failures ? 100.0 * t.successes / (t.episodes - t.plan_failures) : 0.0);
    out << buf << std::endl;
  }
  out << "wrote " << dir << "/summary.json and " << dir << "/episodes.jsonl" << std::endl;
  return kExitOk;
}

}  // namespace simhuman::app
