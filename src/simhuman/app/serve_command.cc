#include "simhuman/app/serve_command.h"

#include <pthread.h>

#include <CLI/CLI.hpp>
#include <csignal>
#include <filesystem>
#include <thread>

#include "simhuman/app/common.h"
#include "simhuman/app/planner_factory.h"
#include "simhuman/core/scene_catalog.h"
#include "simhuman/eval/episode.h"
#include "simhuman/web/server.h"
#include "simhuman/world/scene.h"

namespace simhuman::app {
namespace {

const char kCommand[] = "serve";

}  // namespace

CLI::App* AddServeCommand(CLI::App& app, ServeFlags* flags, CLI::Option** preset) {
  CLI::App* cmd = app.add_subcommand(
      "serve", "Serve a live 3D view of a scene with a command box (open it in a browser)");
  cmd->add_option("--scene", flags->scene,
                  "Built-in scene name (see 'simhuman scenes') or scene JSON file")
      ->required();
  cmd->add_option("--port", flags->port, "TCP port (0: any free port)")->capture_default_str();
  cmd->add_option("--bind", flags->bind,
                  "Address to listen on; anything but 127.0.0.1 lets other machines in")
      ->capture_default_str();
  cmd->add_option("--planner", flags->planner,
                  "Planner for commands: " + core::JoinNames(PlannerNames()))
      ->capture_default_str();
  AddLlmFlags(*cmd, flags->llm);
  cmd->add_option("--seed", flags->seed, "Random seed of the controllers")->capture_default_str();
  *preset = cmd->add_option("--preset", flags->preset, "MPC preset: fast or quality")
                ->capture_default_str();
  cmd->add_option("--config", flags->config, "MPC settings JSON file (keys of MpcConfig)");
  cmd->add_option("--policy", flags->policy,
                  "Walking policy for get-close steps (default assets/policies/walk.pt if "
                  "present)");
  cmd->add_flag("--no-walk", flags->no_walk, "Do get-close steps with the MPC only");
  cmd->add_option("--speed", flags->speed,
                  "Simulated seconds per wall second (0: as fast as the machine goes)")
      ->capture_default_str();
  return cmd;
}

int ServeCommand(const ServeFlags& flags, std::ostream& out, std::ostream& err) {
  core::StatusOr<control::MpcConfig> config =
      ResolveConfig(flags.preset, flags.preset_given, flags.config);
  if (!config.ok()) return ReportError(err, kCommand, config.status());
  core::StatusOr<world::SceneSpec> scene = world::LoadScene(flags.scene);
  if (!scene.ok()) return ReportError(err, kCommand, core::Annotate(scene.status(), "--scene"));
  core::StatusOr<std::unique_ptr<language::Planner>> planner =
      MakePlanner(flags.planner, flags.llm);
  if (!planner.ok()) return ReportError(err, kCommand, planner.status());
  web::LiveOptions live;
  live.config = *config;
  live.seed = flags.seed;
  live.speed = flags.speed;
  live.walk_policy = flags.no_walk ? "" : eval::DefaultWalkPolicy(flags.policy);
  absl::Status valid = live.Validate();
  if (!valid.ok()) return ReportError(err, kCommand, core::Annotate(valid, "--speed"));
  std::error_code ec;
  if (!flags.policy.empty() && !flags.no_walk &&
      !std::filesystem::is_regular_file(flags.policy, ec)) {
    return ReportError(err, kCommand,
                       absl::InvalidArgumentError("--policy: no policy file '" + flags.policy +
                                                  "' (a walking policy, e.g. "
                                                  "assets/policies/walk.pt)"));
  }

  // SIGINT and SIGTERM go to one waiting thread only (blocked here, before any thread starts)
  sigset_t signals;
  sigemptyset(&signals);
  sigaddset(&signals, SIGINT);
  sigaddset(&signals, SIGTERM);
  pthread_sigmask(SIG_BLOCK, &signals, nullptr);

  web::ServerOptions server_options;
  server_options.bind = flags.bind;
  server_options.port = flags.port;
  // the address first: a port in use is said before seconds go into building the session
  web::LiveServer server(nullptr, server_options);
  absl::Status bound = server.Bind();
  if (!bound.ok()) {
    err << "simhuman serve: error: " << bound.message() << std::endl;
    return kExitInternal;
  }
  core::StatusOr<std::unique_ptr<web::LiveSession>> session =
      web::LiveSession::Start(*scene, std::move(*planner), live);
  if (!session.ok()) return ReportError(err, kCommand, session.status());
  server.set_session(session->get());
  if (flags.bind != "127.0.0.1" && flags.bind != "localhost") {
    err << "simhuman serve: warning: listening on " << flags.bind
        << ": other machines can reach this server, and it has no authentication" << std::endl;
  }
  out << "simhuman serve: scene " << scene->name << ", preset " << config->preset << ", planner "
      << flags.planner << "; open http://" << flags.bind << ":" << server.port()
      << "/ (Ctrl-C stops)" << std::endl;
  std::thread waiter([&server, signals] {
    int sig = 0;
    sigwait(&signals, &sig);
    server.Stop();
  });
  server.Serve();
  // Serve() also returns when listening fails; wake the waiter so it can be joined
  pthread_kill(waiter.native_handle(), SIGTERM);
  waiter.join();
  out << "simhuman serve: stopped" << std::endl;
  return kExitOk;
}

}  // namespace simhuman::app
