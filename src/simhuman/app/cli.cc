#include "simhuman/app/cli.h"

#include <mujoco/mujoco.h>

#include <CLI/CLI.hpp>
#include <cerrno>
#include <cstdlib>
#include <iostream>
#include <optional>
#include <sstream>

#include "simhuman/app/clip_command.h"
#include "simhuman/app/common.h"
#include "simhuman/app/eval_command.h"
#include "simhuman/app/export_command.h"
#include "simhuman/app/plan_command.h"
#include "simhuman/app/planner_factory.h"
#include "simhuman/app/replay_command.h"
#include "simhuman/app/run_command.h"
#include "simhuman/app/serve_command.h"
#include "simhuman/app/train_command.h"
#include "simhuman/core/version.h"
#include "simhuman/dist/mpi_communicator.h"
#include "simhuman/eval/suites.h"
#include "simhuman/learn/tasks.h"
#include "simhuman/world/health.h"
#include "simhuman/world/scene.h"
#include "simhuman/world/tabletop.h"

namespace simhuman::app {
namespace {

constexpr char kVersion[] = "0.1.0";

// `simhuman scenes`: the built-in scenes with their objects and humans
int ScenesCommand(std::ostream& out, std::ostream& err) {
  for (const std::string& name : world::BuiltinSceneNames()) {
    core::StatusOr<world::SceneSpec> spec = world::BuiltinScene(name);
    if (!spec.ok()) return ReportError(err, "scenes", absl::InternalError(spec.status().message()));
    out << name << ": " << spec->humans.size() << (spec->humans.size() == 1 ? " human" : " humans")
        << "; objects: ";
    if (spec->objects.empty()) out << "(none)";
    for (size_t i = 0; i < spec->objects.size(); ++i) {
      out << (i ? ", " : "") << spec->objects[i].id << " (" << spec->objects[i].type << ")";
    }
    out << std::endl;
  }
  return kExitOk;
}

// seeds are unsigned 64-bit integers; CLI11 would wrap "-3" around
CLI::Validator SeedValidator() {
  return CLI::Validator(
      [](std::string& value) -> std::string {
        errno = 0;
        bool digits = !value.empty() && value.find_first_not_of("0123456789") == std::string::npos;
        if (digits) std::strtoull(value.c_str(), nullptr, 10);
        if (!digits || errno == ERANGE) {
          return "seed '" + value + "' is invalid; valid: an integer in [0, 2^64)";
        }
        return "";
      },
      "UINT");
}

// the subcommand's name for messages ("" for the top level)
std::string ParsedCommand(const CLI::App& app) {
  for (const CLI::App* sub : app.get_subcommands()) return sub->get_name();
  return "";
}

// `simhuman export-policy`'s flags
struct ExportFlags {
  std::string checkpoint, out, eval_summary;
};

// `simhuman clip`'s two subcommands
struct ClipCommands {
  CLI::App* convert = nullptr;
  CLI::App* gait = nullptr;
};

// `simhuman run`: its flags into `run`; `preset` tells later whether --preset was given
CLI::App* AddRunCommand(CLI::App& app, RunFlags* run, CLI::Option** preset) {
  CLI::App* run_cmd = app.add_subcommand("run", "Run one plan in one scene and write the results");
  run_cmd
      ->add_option("--scene", run->scene,
                   "Built-in scene name (see 'simhuman scenes') or scene JSON file")
      ->required();
  run_cmd->add_option("--plan", run->plan,
                      "Chain-of-Contacts plan JSON file (this or --command is required)");
  run_cmd->add_option("--command", run->command,
                      "Text command to plan and run instead of --plan, e.g. \"sit on the chair\"");
  run_cmd
      ->add_option("--planner", run->planner,
                   "Planner for --command: " + core::JoinNames(PlannerNames()))
      ->capture_default_str();
  AddLlmFlags(*run_cmd, run->llm);
  run_cmd->add_option("--seed", run->seed, "Random seed of the controllers")
      ->check(SeedValidator())
      ->capture_default_str();
  *preset = run_cmd->add_option("--preset", run->preset, "MPC preset: fast or quality")
                ->capture_default_str();
  run_cmd->add_option("--config", run->config, "MPC settings JSON file (keys of MpcConfig)");
  run_cmd->add_option("--out", run->out, "Output folder")->capture_default_str();
  run_cmd->add_flag("--video", run->video, "Also render DIR/video.mp4 and DIR/contact_sheet.png");
  run_cmd->add_flag("--html", run->html, "Also write DIR/replay.html (open it in a browser)");
  run_cmd->add_option("--policy", run->policy,
                      "Walking policy for get-close steps (default assets/policies/walk.pt if "
                      "present)");
  run_cmd->add_flag("--no-walk", run->no_walk, "Do get-close steps with the MPC only");
  run_cmd->add_option("--carry-policy", run->carry_policy,
                      "Carrying policy for carry steps (default assets/policies/carry.pt)");
  run_cmd
      ->add_option("--perception", run->perception,
                   "Tabletop plans: truth (the objects' true state) or vision (the head camera)")
      ->check(CLI::IsMember({"truth", "vision"}))
      ->capture_default_str();
  run_cmd->add_option("--vision-model", run->vision_model,
                      "Tabletop plans with --perception vision: model file (default "
                      "assets/vision/vision.pt)");
  run_cmd->add_option("--grasp-policy", run->grasp_policy,
                      "Tabletop plans: grasp policy file or 'scripted' (default "
                      "assets/policies/grasp.pt if present, else scripted)");
  run_cmd
      ->add_option("--place-policy", run->place_policy,
                   "Tabletop plans: place policy file (simhuman train --task place) or 'scripted'")
      ->capture_default_str();
  run_cmd->add_option("--start", run->start,
                      "Where the first human starts, standing: X,Y[,YAW_DEG] (m, degrees; "
                      "overrides the scene)");
  run_cmd->add_option("--settle", run->settle_s, "Seconds to keep simulating after the last step")
      ->capture_default_str();
  return run_cmd;
}

// `simhuman eval`: its flags into `ev`; `preset` tells later whether --preset was given
CLI::App* AddEvalCommand(CLI::App& app, EvalFlags* ev, CLI::Option** preset) {
  std::string suites = core::JoinNames(eval::SuiteNames());
  CLI::App* eval_cmd = app.add_subcommand("eval", "Run a benchmark suite of random episodes");
  eval_cmd->add_option("--suite", ev->suite, "Suite: " + suites)->required();
  eval_cmd->add_option("--episodes", ev->episodes, "Number of episodes")->capture_default_str();
  eval_cmd->add_option("--seed", ev->seed, "Seed of the suite (episode i uses DeriveSeed(seed, i))")
      ->check(SeedValidator())
      ->capture_default_str();
  eval_cmd->add_option("--out", ev->out, "Output folder (default out/eval_<suite>)");
  *preset = eval_cmd->add_option("--preset", ev->preset, "MPC preset: fast or quality")
                ->capture_default_str();
  eval_cmd->add_option("--config", ev->config, "MPC settings JSON file (keys of MpcConfig)");
  eval_cmd->add_option("--corpus", ev->corpus,
                       "language suite: command corpus (JSON lines; default: the one in the "
                       "sources)");
  eval_cmd->add_option("--planner", ev->planner, "language suite: planner")->capture_default_str();
  AddLlmFlags(*eval_cmd, ev->llm);
  eval_cmd
      ->add_option("--video-every", ev->video_every,
                   "Render every K-th episode's contact sheet to DIR/ep<i>.png (0: none)")
      ->capture_default_str();

  eval_cmd->add_option("--policy", ev->policy,
                       "Walking policy file (walk suite; get-close steps of other suites)");
  eval_cmd->add_option("--grasp-policy", ev->grasp_policy,
                       "tabletop, place, stack: grasp policy file or 'scripted' (default "
                       "assets/policies/grasp.pt if present, else scripted)");
  eval_cmd
      ->add_option("--place-policy", ev->place_policy,
                   "tabletop, place, stack: place policy file (simhuman train --task place: "
                   "corrections to the scripted placing) or 'scripted'")
      ->capture_default_str();
  eval_cmd
      ->add_option("--grasp-attempts", ev->grasp_attempts,
                   "tabletop, place, stack: grasps tried on one object before a miss ends the "
                   "episode (1: no second try, as DASH)")
      ->check(CLI::Range(1, 5))
      ->capture_default_str();
  eval_cmd
      ->add_option("--planner-seed", ev->planner_seed,
                   "tabletop, place, stack: the seed of every arm plan's search (RRTConnect); "
                   "the outcome of some episodes turns on it, so compare runs over several")
      ->check(CLI::Range(1, 1000000))
      ->capture_default_str();
  eval_cmd
      ->add_option("--zero-shot", ev->zero_shot,
                   "tabletop, place, stack: the task object becomes a shape the pipeline was not "
                   "made for (cone, hourglass, or mesh: an OBJ file, --zero-shot-mesh); ground "
                   "truth only")
      ->check(CLI::IsMember(world::ZeroShotShapes()));
  eval_cmd->add_option("--zero-shot-mesh", ev->zero_shot_mesh,
                       "tabletop, place, stack with --zero-shot mesh: the OBJ file (metres, +z "
                       "up; default assets/meshes/vase.obj)");
  eval_cmd->add_option("--approach-policy", ev->approach_policy,
                       "carry: a walking policy file (e.g. assets/policies/walk.pt) that walks up "
                       "to the box; the carry policy takes over at the lift");
  eval_cmd->add_option("--walker", ev->walker,
                       "carry: a walking policy file (e.g. assets/policies/walk.pt) that walks "
                       "up to the box, carries it and steps back");
  eval_cmd->add_option("--lift-policy", ev->lift_policy,
                       "carry: a lift policy file (simhuman train --task carry-lift) that lifts "
                       "the box");
  eval_cmd->add_option("--deliver-policy", ev->deliver_policy,
                       "carry: a delivery policy file (simhuman train --task carry-deliver) that "
                       "carries the box and puts it down");
  eval_cmd->add_flag("--model-squats", ev->model_squats,
                     "carry: lift and put down with the model-based controller (keyframes and "
                     "quasi-static support, no policy)");
  eval_cmd
      ->add_option("--first-episode", ev->first_episode,
                   "tabletop, place, stack: start at this episode of the seed's run (e.g. 200 "
                   "with --episodes 200: the next 200 scenes after the suite's)")
      ->check(CLI::Range(0, 1000000))
      ->capture_default_str();
  eval_cmd
      ->add_option("--jobs", ev->jobs,
                   "tabletop, place, stack: episodes run at once, one thread each (results do "
                   "not depend on it; 2 uses both cores of a 2-core machine)")
      ->check(CLI::Range(1, 64))
      ->capture_default_str();
  eval_cmd->add_option("--vision-model", ev->vision_model,
                       "vision suite, --perception vision: model file (default "
                       "assets/vision/vision.pt)");
  eval_cmd
      ->add_option("--perception", ev->perception,
                   "tabletop, place, stack: truth (the objects' true state) or vision (the "
                   "head camera)")
      ->check(CLI::IsMember({"truth", "vision"}))
      ->capture_default_str();
  eval_cmd->add_flag("--no-touch", ev->no_touch,
                     "tabletop, place, stack with --perception vision: the object grasped and "
                     "held is placed by the camera and the grasp prior alone, without the "
                     "hand's touch (an ablation)");
  eval_cmd->add_flag("--no-silhouette", ev->no_silhouette,
                     "vision, and tabletop, place, stack with --perception vision: the task "
                     "planner reads the vision network's estimates as they are, without fitting "
                     "them to the objects' outlines in the frame (an ablation)");
  eval_cmd->add_flag("--video", ev->video, "walk suite: also write MP4s of rendered episodes");
  eval_cmd
      ->add_option("--physics-solver", ev->physics_solver,
                   "walk suites: MuJoCo solver, newton or pgs (e.g. to check a policy trained "
                   "with physics_solver pgs)")
      ->capture_default_str();
  eval_cmd
      ->add_option("--scales", ev->scales,
                   "walk suites: body length scales, one run each with success per scale "
                   "(e.g. 0.6,0.8,1.0,1.2; each in [0.5, 1.5]; default 1)")
      ->delimiter(',');
  eval_cmd->add_flag("--resume", ev->resume,
                     "Plan suites: continue the run in --out, running only its missing episodes");
  return eval_cmd;
}

// `simhuman plan`: its flags into `pl`
CLI::App* AddPlanCommand(CLI::App& app, PlanFlags* pl) {
  CLI::App* plan_cmd =
      app.add_subcommand("plan", "Turn a text command into a Chain-of-Contacts plan and print it");
  plan_cmd
      ->add_option("--scene", pl->scene,
                   "Built-in scene name (see 'simhuman scenes') or scene JSON file")
      ->required();
  plan_cmd->add_option("--command", pl->command, "The command, e.g. \"sit on the sofa\"")
      ->required();
  plan_cmd->add_flag("--explain", pl->explain, "Also print one line per step in words");
  plan_cmd->add_option("--planner", pl->planner, "Planner: " + core::JoinNames(PlannerNames()))
      ->capture_default_str();
  plan_cmd->add_option("--out", pl->out, "Also write the plan JSON to this file");
  AddLlmFlags(*plan_cmd, pl->llm);
  return plan_cmd;
}

// `simhuman train`: its flags into `tf`; `steps` and `seed` tell later whether --steps and
// --seed were given
CLI::App* AddTrainCommand(CLI::App& app, TrainFlags* tf, CLI::Option** steps, CLI::Option** seed) {
  CLI::App* train_cmd = app.add_subcommand("train", "Train a policy with PPO (resumable)");
  std::string tasks;
  for (const std::string& t : learn::TaskNames()) tasks += (tasks.empty() ? "" : ", ") + t;
  train_cmd
      ->add_option(
          "--task", tf->task,
          "Task: one of " + tasks + ", vision (default: the --config file's task, else walk)")
      ->each([tf](const std::string&) { tf->task_given = true; });
  *steps = train_cmd->add_option("--steps", tf->steps, "Total env steps (30M, 500k)")
               ->capture_default_str();
  train_cmd->add_option("--out", tf->out, "Run folder of a new run");
  train_cmd->add_option("--resume", tf->resume, "Run folder to continue from its checkpoint");
  train_cmd->add_option(
      "--config", tf->config,
      "PPO settings JSON file (keys of PpoConfig); with --resume, the schedule keys to change");
  *seed = train_cmd->add_option("--seed", tf->seed, "Seed of the run")
              ->check(SeedValidator())
              ->capture_default_str();
  train_cmd->add_option("--envs", tf->envs, "Parallel environments")->check(CLI::Range(1, 4096));
  train_cmd->add_option("--threads", tf->threads, "Worker threads")->check(CLI::Range(1, 64));
  train_cmd->add_flag("--quiet", tf->quiet, "No progress bar");
  train_cmd->add_option("--init-from", tf->init_from,
                        "Policy file (e.g. assets/policies/walk.pt) a new run's policy starts from "
                        "(fine-tuning; the value network starts fresh)");
  train_cmd->add_option("--amp-clips", tf->amp_clips,
                        "Comma-separated motion clips (.clip.json) or BVH files: turns on AMP "
                        "(walk task)");
  return train_cmd;
}

// `simhuman clip convert` and `simhuman clip gait`: their flags into `cf`
ClipCommands AddClipCommands(CLI::App& app, ClipFlags* cf) {
  ClipCommands cmds;
  CLI::App* clip_cmd = app.add_subcommand("clip", "Make motion clips for AMP (convert, gait)");
  clip_cmd->require_subcommand(1);
  cmds.convert = clip_cmd->add_subcommand("convert", "Retarget a BVH file to a clip");
  cmds.convert->add_option("--bvh", cf->bvh, "BVH file (CMU-style)")->required();
  cmds.convert->add_option("--out", cf->out, "Clip file to write (.clip.json)")->required();
  cmds.convert->add_option("--fps", cf->fps, "Resample to this frame rate (default: the BVH's)");
  cmds.gait = clip_cmd->add_subcommand("gait", "Write the walking task's reference gait as a clip");
  cmds.gait->add_option("--out", cf->out, "Clip file to write (.clip.json)")->required();
  cmds.gait->add_option("--seconds", cf->seconds, "Length in seconds")->capture_default_str();
  cmds.gait->add_option("--speed", cf->speed_mps, "Forward speed, m/s")->capture_default_str();
  cmds.gait->add_option("--fps", cf->fps, "Frame rate (default 30)");
  return cmds;
}

// `simhuman export-policy`: its flags into `ex`
CLI::App* AddExportCommand(CLI::App& app, ExportFlags* ex) {
  CLI::App* export_cmd =
      app.add_subcommand("export-policy", "Write the small policy file of a checkpoint");
  export_cmd->add_option("--checkpoint", ex->checkpoint, "checkpoint.pt or policy file")
      ->required();
  export_cmd->add_option("--out", ex->out, "Policy file to write")->required();
  export_cmd->add_option("--eval-summary", ex->eval_summary,
                         "summary.json of a `simhuman eval` of this policy (provenance)");
  return export_cmd;
}

// `simhuman export`: its flags into `xf`
CLI::App* AddExportRunCommand(CLI::App& app, ExportRunFlags* xf) {
  CLI::App* cmd = app.add_subcommand(
      "export", "Export a finished run as BVH motion (--bvh) and an animated glTF scene (--gltf)");
  cmd->add_option("run_dir", xf->run_dir, "The run's folder (simhuman run --out DIR)")->required();
  cmd->add_option("--bvh", xf->bvh,
                  "BVH file to write; with several humans one per human: NAME_h0.bvh, "
                  "NAME_h1.bvh, ... (unless --agent)");
  cmd->add_option("--gltf", xf->gltf, "glTF 2.0 binary file (.glb) to write");
  cmd->add_option("--agent", xf->agent, "Export only this human's BVH (0-based)");
  cmd->add_option("--fps", xf->fps, "Sample rate (default: the run's, 30)");
  cmd->add_option("--video", xf->video, "Render the run again into this MP4 (needs plan.json)");
  cmd->add_option("--sheet", xf->sheet, "Render a contact sheet PNG (needs plan.json)");
  cmd->add_flag("--shadows", xf->shadows, "Video and sheet with shadows (several times slower)");
  cmd->add_flag("--fixed-camera", xf->fixed_camera,
                "Video and sheet from the fixed side-front camera (no occlusion avoidance)");
  return cmd;
}

// parses `args` into `app`'s flags; returns the exit code when that already ends the run (help,
// version, a parse error), nullopt when the parsed command is to run
std::optional<int> ParseArgs(CLI::App& app, const std::vector<std::string>& args, std::ostream& out,
                             std::ostream& err) {
  std::vector<const char*> argv;
  for (const std::string& a : args) argv.push_back(a.c_str());
  try {
    app.parse(static_cast<int>(argv.size()), argv.data());
  } catch (const CLI::CallForHelp&) {
    out << app.help();  // the selected subcommand's, when there is one
    return kExitOk;
  } catch (const CLI::CallForAllHelp&) {
    out << app.help("", CLI::AppFormatMode::All);
    return kExitOk;
  } catch (const CLI::CallForVersion& e) {
    out << e.what() << std::endl;
    return kExitOk;
  } catch (const CLI::ParseError& e) {
    std::string cmd = ParsedCommand(app);
    std::string msg = e.what();
    for (char& c : msg) {
      if (c == '\n') c = ' ';
    }
    err << "simhuman" << (cmd.empty() ? "" : " " + cmd) << ": error: " << msg << "; run 'simhuman"
        << (cmd.empty() ? "" : " " + cmd) << " --help' for the valid options" << std::endl;
    return kExitBadInput;
  }
  return std::nullopt;
}

}  // namespace

std::string VersionText() {
  return std::string("simhuman ") + kVersion + " (git " + std::string(core::GitRevision()) +
         ", MuJoCo " + mj_versionString() + ")";
}

int RunCli(const std::vector<std::string>& args, std::ostream& out, std::ostream& err) {
  core::SerialCommunicator serial;
  return RunCli(args, out, err, serial);
}

int RunCli(const std::vector<std::string>& args, std::ostream& out, std::ostream& err,
           core::Communicator& comm) {
  CLI::App app{"simhuman: simulated humans that carry out Chain-of-Contacts plans", "simhuman"};
  app.set_version_flag("--version", VersionText(), "Print the version and exit");
  app.require_subcommand(0, 1);

  RunFlags run;
  CLI::Option* run_preset = nullptr;
  CLI::App* run_cmd = AddRunCommand(app, &run, &run_preset);
  EvalFlags ev;
  CLI::Option* eval_preset = nullptr;
  CLI::App* eval_cmd = AddEvalCommand(app, &ev, &eval_preset);
  PlanFlags pl;
  CLI::App* plan_cmd = AddPlanCommand(app, &pl);
  app.add_subcommand("scenes", "List the built-in scenes and their objects");
  TrainFlags tf;
  CLI::Option* steps_opt = nullptr;
  CLI::Option* seed_opt = nullptr;
  CLI::App* train_cmd = AddTrainCommand(app, &tf, &steps_opt, &seed_opt);
  ClipFlags cf;
  const ClipCommands clip = AddClipCommands(app, &cf);
  ExportFlags ex;
  CLI::App* export_cmd = AddExportCommand(app, &ex);
  ExportRunFlags xf;
  CLI::App* export_run_cmd = AddExportRunCommand(app, &xf);
  ReplayFlags rf;
  CLI::App* replay_cmd = AddReplayCommand(app, &rf);
  ServeFlags sf;
  CLI::Option* serve_preset = nullptr;
  CLI::App* serve_cmd = AddServeCommand(app, &sf, &serve_preset);

  std::ostringstream parse_err;
  std::optional<int> code = ParseArgs(app, args, out, parse_err);
  if (comm.size() > 1) {
    // a rank whose command line does not parse stops every rank
    std::string msg = parse_err.str();
    if (!msg.empty() && msg.back() == '\n') msg.pop_back();
    absl::Status st = code && *code != kExitOk ? absl::InvalidArgumentError(msg) : absl::OkStatus();
    st = core::AgreeOk(comm, st);
    if (!st.ok()) {
      err << "simhuman: error: " << st.message() << std::endl;
      return kExitBadInput;
    }
  }
  err << parse_err.str();
  if (code) return *code;

  if (run_cmd->parsed()) {
    run.preset_given = run_preset->count() > 0;
    return RunCommand(run, out, err);
  }
  if (eval_cmd->parsed()) {
    ev.preset_given = eval_preset->count() > 0;
    return EvalCommand(ev, out, err, comm);
  }
  if (plan_cmd->parsed()) return PlanCommand(pl, out, err);
  if (app.got_subcommand("scenes")) return ScenesCommand(out, err);
  if (train_cmd->parsed()) {
    tf.steps_given = steps_opt->count() > 0;
    tf.seed_given = seed_opt->count() > 0;
    return TrainCommand(tf, out, err, comm);
  }
  if (replay_cmd->parsed()) return ReplayCommand(rf, out, err);
  if (serve_cmd->parsed()) {
    sf.preset_given = serve_preset->count() > 0;
    return ServeCommand(sf, out, err);
  }
  if (clip.convert->parsed()) return ClipConvertCommand(cf, out, err);
  if (clip.gait->parsed()) return ClipGaitCommand(cf, out, err);
  if (export_run_cmd->parsed()) return ExportRunCommand(xf, out, err);
  if (export_cmd->parsed()) {
    return ExportPolicyCommand(ex.checkpoint, ex.out, ex.eval_summary, out, err);
  }
  err << "simhuman: error: a command is required; valid commands are: run, plan, eval, scenes, "
         "train, export-policy, export, clip, replay, serve (or "
         "--version, --help)"
      << std::endl;
  return kExitBadInput;
}

int Main(int argc, char** argv) {
  world::InstallMujocoHandlers();
  std::vector<std::string> args(argv, argv + argc);
  if (args.empty()) args.push_back("simhuman");
  core::StatusOr<std::unique_ptr<core::Communicator>> comm = dist::StartCommunicator();
  if (!comm.ok()) return ReportError(std::cerr, "mpi", comm.status());
  core::Communicator& c = **comm;
  // only rank 0 prints: every error reaches it (core::AgreeOk)
  std::ostream null_stream(nullptr);
  std::ostream& out = c.rank() == 0 ? std::cout : null_stream;
  std::ostream& err = c.rank() == 0 ? std::cerr : null_stream;
  if (c.size() > 1) {
    // ranks started from different builds would not compute the same thing
    core::StatusOr<std::string> exe = core::FileHashHex("/proc/self/exe");
    absl::Status st = core::AgreeOk(c, exe.status());
    if (st.ok()) st = core::CheckSameOnAllRanks(c, "simhuman binaries", VersionText() + *exe);
    if (!st.ok()) return ReportError(err, "mpi", st);
  }
  return RunCli(args, out, err, c);
}

}  // namespace simhuman::app
