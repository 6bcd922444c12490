#include "simhuman/app/run_command.h"

#include <cmath>
#include <cstdio>
#include <filesystem>

#include "absl/strings/numbers.h"
#include "absl/strings/str_split.h"
#include "simhuman/app/common.h"
#include "simhuman/app/plan_command.h"
#include "simhuman/app/vision_command.h"
#include "simhuman/control/runner.h"
#include "simhuman/eval/episode.h"
#include "simhuman/eval/eval_runner.h"
#include "simhuman/eval/motion_metrics.h"
#include "simhuman/eval/reachability.h"
#include "simhuman/eval/replay.h"
#include "simhuman/eval/tabletop_eval.h"
#include "simhuman/plan/validate.h"
#include "simhuman/web/replay_html.h"
#include "simhuman/world/scene.h"

namespace simhuman::app {
namespace {

// --start "X,Y[,YAW_DEG]": the first human stands there (checked like a scene file's human)
core::StatusOr<world::SceneSpec> PlaceFirstHuman(world::SceneSpec scene, const std::string& text) {
  std::vector<double> v;
  for (absl::string_view part : absl::StrSplit(text, ',')) {
    double x = 0;
    if (!absl::SimpleAtod(part, &x) || !std::isfinite(x)) {
      v.clear();
      break;
    }
    v.push_back(x);
  }
  if (v.size() != 2 && v.size() != 3) {
    return absl::InvalidArgumentError("--start '" + text +
                                      "' is invalid; valid: X,Y or X,Y,YAW_DEG (finite numbers, "
                                      "metres and degrees), e.g. --start 0,-1,90");
  }
  if (scene.humans.empty()) scene.humans.emplace_back();
  world::HumanSpec& h = scene.humans[0];
  h.pos_xy = Eigen::Vector2d(v[0], v[1]);
  if (v.size() == 3) h.yaw_rad = v[2] * M_PI / 180.0;
  h.posture = "stand";
  core::StatusOr<world::SceneSpec> checked =
      world::ParseSceneJson(world::SceneToJson(scene), "--start");
  if (!checked.ok()) return checked.status();
  checked->name = scene.name;
  return checked;
}

const char kCommand[] = "run";

std::string Fixed(double v, int digits) {
  char buf[48];
  std::snprintf(buf, sizeof(buf), "%.*f", digits, v);
  return buf;
}

std::string Plural(size_t n, const std::string& word) {
  return std::to_string(n) + " " + word + (n == 1 ? "" : "s");
}

std::string Join(const std::filesystem::path& dir, const char* name) {
  return (dir / name).string();
}

// one progress line per completed (or abandoned) step
void PrintProgress(std::ostream& out, const plan::ContactChain& chain,
                   const control::ProgressEvent& e) {
  if (e.ended) return;
  const int n = static_cast<int>(chain.steps.size());
  const int i = std::clamp(e.step, 0, n - 1);
  out << "step " << i + 1 << "/" << n << " '" << eval::StepText(chain.steps[i]) << "' "
      << (e.completed ? "done" : "not done, time budget used up") << " at t=" << Fixed(e.time_s, 2)
      << " s (distance " << Fixed(e.distance_m, 3) << " m)" << std::endl;
}

// --html: DIR/replay.html, the run in one web page; false (the error on `err`) on failure
bool WriteRunPage(const RunFlags& flags, const std::string& scene_name, const world::SimWorld& sim,
                  const plan::ContactChain& chain, const control::Trajectory& trajectory,
                  const nlohmann::ordered_json& j, std::ostream& out, std::ostream& err) {
  web::ReplayHtmlOptions page;
  page.title = "simhuman run: " + scene_name +
               (flags.command.empty() ? std::string() : ", \"" + flags.command + "\"");
  const std::string path = Join(flags.out, "replay.html");
  absl::Status st =
      web::WriteReplayHtml(path, sim, chain, trajectory, nlohmann::json::parse(j.dump()), page);
  if (!st.ok()) {
    err << "simhuman run: error: writing the replay page failed (the results are in "
        << Join(flags.out, "result.json") << "): " << st.message() << std::endl;
    return false;
  }
  out << "replay page: " << path << std::endl;
  return true;
}

// human-norm motion metrics per human, from the recorded frames (eval/motion_metrics.h)
nlohmann::ordered_json MotionJson(const world::SimWorld& sim, const control::Trajectory& traj) {
  nlohmann::ordered_json motion = nlohmann::ordered_json::array();
  for (int a = 0; a < sim.num_agents(); ++a) {
    motion.push_back(
        eval::MotionMetricsJson(eval::TrajectoryMotionMetrics(sim, a, traj.time_s, traj.qpos)));
  }
  return motion;
}

}  // namespace

namespace {
// the vision model a tabletop run plans and watches with ("" without --perception vision)
std::string VisionModelFor(const RunFlags& f) {
  if (f.perception != "vision") return "";
  return f.vision_model.empty() ? DefaultVisionModel() : f.vision_model;
}

// the run's one-line summary and its warnings
void PrintRunResult(const control::EpisodeResult& result, bool stands_at_end,
                    const std::string& result_path, std::ostream& out, std::ostream& err) {
  out << "success: " << (result.success ? "yes" : "no") << ", steps " << result.steps_completed
      << "/" << result.steps_total << ", contact error "
      << (result.contact_error_m >= 0 ? Fixed(result.contact_error_m, 3) + " m" : "n/a")
      << ", fell: " << (result.fell ? "yes" : "no") << ", end: " << result.end_reason << ", sim "
      << Fixed(result.sim_time_s, 2) << " s, wall " << Fixed(result.wall_time_s, 2) << " s ("
      << (result.sim_time_s > 0 ? Fixed(result.wall_time_s / result.sim_time_s, 2) : "n/a")
      << " wall/sim); results in " << result_path << std::endl;
  if (result.success && !stands_at_end) {
    err << "simhuman run: warning: the plan's last step asks the human to stand, and it is not "
           "standing at the end (the success above follows UniHSI's rule: the pelvis's position "
           "only; the eval suites count this as a failure)"
        << std::endl;
  }
  if (result.success && !result.success_unihsi_points) {
    out << "note: on UniHSI's body points (the pelvis point between the hips, a hand on the "
           "pelvis measured to that point) the plan is not met: success_unihsi_points false in "
        << result_path << std::endl;
  }
  if (result.end_reason.rfind("unstable", 0) == 0 ||
      result.end_reason.rfind("controller", 0) == 0) {
    err << "simhuman run: warning: the episode ended early: " << result.end_reason << std::endl;
  }
}
}  // namespace

int RunCommand(const RunFlags& flags, std::ostream& out, std::ostream& err) {
  // flags that need no files
  if (flags.plan.empty() == flags.command.empty()) {
    return ReportError(err, kCommand,
                       absl::InvalidArgumentError(
                           "exactly one of --plan FILE (a Chain-of-Contacts plan, e.g. "
                           "assets/plans/sit_then_stand.json) and --command TEXT (e.g. \"sit on "
                           "the chair\") is required"));
  }
  if (!std::isfinite(flags.settle_s) || flags.settle_s < 0) {
    return ReportError(err, kCommand,
                       absl::InvalidArgumentError("--settle " + std::to_string(flags.settle_s) +
                                                  " is invalid; valid: a finite number of "
                                                  "seconds >= 0"));
  }
  core::StatusOr<control::MpcConfig> config =
      ResolveConfig(flags.preset, flags.preset_given, flags.config);
  if (!config.ok()) return ReportError(err, kCommand, config.status());

  // scene, plan and whether it can be done from where the humans start
  core::StatusOr<world::SceneSpec> scene = world::LoadScene(flags.scene);
  if (!scene.ok()) return ReportError(err, kCommand, scene.status());
  if (!flags.start.empty()) {
    scene = PlaceFirstHuman(*scene, flags.start);
    if (!scene.ok()) return ReportError(err, kCommand, scene.status());
  }
  core::StatusOr<core::SceneCatalog> catalog = world::BuildCatalog(*scene);
  if (!catalog.ok()) return ReportError(err, kCommand, catalog.status());
  core::StatusOr<plan::ContactChain> chain = absl::UnknownError("no plan");
  if (!flags.command.empty()) {
    core::StatusOr<language::PlanResult> planned =
        PlanCommandText(flags.planner, flags.llm, flags.command, *scene, *catalog);
    if (!planned.ok()) {
      // an ambiguous command (a clarifying question) is bad input too
      const int code = ReportError(err, kCommand, core::Annotate(planned.status(), "--command"));
      return absl::IsFailedPrecondition(planned.status()) ? kExitBadInput : code;
    }
    chain = std::move(planned->chain);
    for (size_t i = 0; i < planned->explanation.size(); ++i) {
      out << "plan step " << i + 1 << ": " << planned->explanation[i] << std::endl;
    }
  } else {
    chain = plan::LoadAndGroundFile(flags.plan, *catalog);
  }
  if (!chain.ok()) {
    absl::Status st = chain.status();
    // a missing file's message does not say which flag named it
    if (absl::IsNotFound(st)) st = core::Annotate(st, "--plan");
    return ReportError(err, kCommand, st);
  }
  absl::Status reach = eval::CheckWithinReach(*chain, *catalog, scene->humans);
  if (!reach.ok()) return ReportError(err, kCommand, reach);
  core::StatusOr<std::vector<world::AgentSpec>> placements = eval::AgentSpecs(*scene);
  if (!placements.ok()) return ReportError(err, kCommand, placements.status());

  core::StatusOr<std::unique_ptr<world::SimWorld>> sim = eval::BuildWorld(*scene, *catalog);
  if (!sim.ok()) return ReportError(err, kCommand, sim.status());
  if (absl::Status s = eval::CheckSeatedTabletopPlan(*chain, **sim); !s.ok()) {
    return ReportError(err, kCommand, s);
  }

  absl::Status dir = MakeOutputDir(flags.out);
  if (!dir.ok()) return ReportError(err, kCommand, dir);
  const std::filesystem::path out_dir(flags.out);
  core::StatusOr<std::vector<std::unique_ptr<control::MpcController>>> controllers =
      eval::MakeControllers(**sim, *config, flags.seed);
  if (!controllers.ok()) return ReportError(err, kCommand, controllers.status());

  out << "simhuman run: scene " << scene->name << " (" << Plural(scene->objects.size(), "object")
      << ", " << Plural(scene->humans.size(), "human") << "), plan "
      << (flags.plan.empty() ? "from --command" : flags.plan) << " ("
      << Plural(chain->steps.size(), "step") << "), preset " << config->preset << ", seed "
      << flags.seed << std::endl;

  control::RunOptions options;
  options.settle_s = flags.settle_s;
  options.fall_head_height_m = config->fall_head_height_m;
  options.record = true;
  options.progress = [&](const control::ProgressEvent& e) { PrintProgress(out, *chain, e); };
  control::Trajectory trajectory;
  const std::string walk_policy = flags.no_walk ? "" : eval::DefaultWalkPolicy(flags.policy);
  if (!walk_policy.empty()) out << "walking with the policy " << walk_policy << std::endl;
  const std::string carry_policy = eval::DefaultCarryPolicy(flags.carry_policy);
  if (!carry_policy.empty()) out << "carrying with the policy " << carry_policy << std::endl;
  core::StatusOr<control::EpisodeResult> run_result = absl::UnknownError("not run");
  std::string grasp_policy;
  if (eval::IsTabletopRun(*chain, **sim)) {
    // seated at the table with a dexterous hand: DASH's pipeline instead of the MPC
    grasp_policy = eval::DefaultGraspPolicy(flags.grasp_policy);
    out << "tabletop pipeline, grasping with " << grasp_policy << ", placing with "
        << flags.place_policy << ", perception " << flags.perception << std::endl;
    run_result = eval::RunTabletopPlan(**sim, *chain, grasp_policy, &trajectory,
                                       VisionModelFor(flags), flags.place_policy);
  } else {
    run_result = eval::RunWithWalkPolicy(**sim, *chain, *controllers, walk_policy, options,
                                         &trajectory, carry_policy);
  }
  if (!run_result.ok()) return ReportError(err, kCommand, run_result.status());
  const control::EpisodeResult& result = *run_result;

  // results first, so a rendering failure cannot lose them
  nlohmann::ordered_json j = eval::EpisodeResultJson(result);
  j["seed"] = flags.seed;
  j["preset"] = config->preset;
  j["scene"] = scene->name;
  j["scene_arg"] = flags.scene;
  j["plan"] = flags.plan;
  if (!flags.command.empty()) j["command"] = flags.command;
  j["config"] = config->ToJson();
  j["settle_s"] = flags.settle_s;
  j["walk_policy"] = walk_policy;
  j["carry_policy"] = carry_policy;
  if (!grasp_policy.empty()) j["grasp_policy"] = grasp_policy;
  if (!grasp_policy.empty()) j["place_policy"] = flags.place_policy;
  j["motion"] = MotionJson(**sim, trajectory);
  // a last stand-up or walk-to step: whether its human stands at the end (UniHSI's rule, which
  // `success` follows, reads the pelvis's position only; the eval suites also need this)
  const bool stands_at_end =
      eval::GetCloseHumansStand(chain->steps.back(), control::AllBodyPoints(**sim, (*sim)->data()));
  j["standing_at_end"] = stands_at_end;
  const nlohmann::ordered_json provenance = eval::ProvenanceJson();
  for (const auto& [key, value] : provenance.items()) j[key] = value;
  absl::Status st = eval::WriteJsonFile(Join(out_dir, "scene.json"), world::SceneToJson(*scene));
  if (st.ok())
    st = eval::WriteJsonFile(Join(out_dir, "plan.json"), plan::ContactChainToJson(*chain));
  if (st.ok())
    st = eval::WriteTrajectoryCsv(Join(out_dir, "trajectory.csv"), (*sim)->model(), trajectory);
  if (st.ok()) st = eval::WriteJsonFile(Join(out_dir, "result.json"), j);
  if (!st.ok()) return ReportError(err, kCommand, absl::InternalError(st.message()));

  PrintRunResult(result, stands_at_end, Join(out_dir, "result.json"), out, err);

  if (flags.html && !WriteRunPage(flags, scene->name, **sim, *chain, trajectory, j, out, err)) {
    return kExitInternal;
  }
  if (flags.video) {
    eval::ReplayOptions replay;
    replay.video_path = Join(out_dir, "video.mp4");
    replay.sheet_path = Join(out_dir, "contact_sheet.png");
    absl::Status rs = eval::RenderReplay(**sim, *chain, trajectory, replay);
    if (!rs.ok()) {
      err << "simhuman run: error: rendering the video failed (the results are in "
          << Join(out_dir, "result.json") << "): " << rs.message() << std::endl;
      return kExitInternal;
    }
    out << "video: " << replay.video_path << ", contact sheet: " << replay.sheet_path << std::endl;
  }
  return kExitOk;
}

}  // namespace simhuman::app
