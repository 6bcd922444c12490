#include "simhuman/app/replay_command.h"

#include <CLI/CLI.hpp>
#include <cmath>
#include <filesystem>

#include "simhuman/app/common.h"
#include "simhuman/eval/run_record.h"
#include "simhuman/web/replay_html.h"

namespace simhuman::app {

CLI::App* AddReplayCommand(CLI::App& app, ReplayFlags* flags) {
  CLI::App* cmd = app.add_subcommand(
      "replay", "Write a recorded run as one HTML page that plays it in a browser (offline)");
  cmd->add_option("run_dir", flags->run_dir, "Run folder (simhuman run --out DIR)")->required();
  cmd->add_option("--html", flags->html, "HTML file to write, e.g. replay.html")->required();
  cmd->add_option("--max-fps", flags->max_fps, "Drop frames above this rate")
      ->capture_default_str();
  return cmd;
}

int ReplayCommand(const ReplayFlags& flags, std::ostream& out, std::ostream& err) {
  const char kCommand[] = "replay";
  if (flags.html.empty()) {
    return ReportError(err, kCommand,
                       absl::InvalidArgumentError("--html FILE is required (the page to write, "
                                                  "e.g. --html replay.html)"));
  }
  if (!std::isfinite(flags.max_fps) || flags.max_fps <= 0) {
    return ReportError(err, kCommand,
                       absl::InvalidArgumentError("--max-fps " + std::to_string(flags.max_fps) +
                                                  " is invalid; valid: a number > 0"));
  }
  core::StatusOr<eval::RunRecord> run = eval::LoadRunRecord(flags.run_dir);
  if (!run.ok()) return ReportError(err, kCommand, run.status());
  if (!run->chain) {
    return ReportError(err, kCommand,
                       absl::NotFoundError("run folder '" + flags.run_dir +
                                           "' has no plan.json; a replay page shows the plan's "
                                           "steps (simhuman run --out DIR writes it)"));
  }
  web::ReplayHtmlOptions options;
  options.max_fps = flags.max_fps;
  options.title = "simhuman replay: " + run->scene.name;
  if (run->result.is_object() && run->result.contains("command") &&
      run->result["command"].is_string()) {
    options.title += ", \"" + run->result["command"].get<std::string>() + "\"";
  }
  absl::Status st = web::WriteReplayHtml(flags.html, *run->world, *run->chain, run->trajectory,
                                         run->result, options);
  if (!st.ok()) return ReportError(err, kCommand, st);
  std::error_code ec;
  const auto bytes = std::filesystem::file_size(flags.html, ec);
  out << "replay: " << flags.html << " (" << run->trajectory.qpos.size() << " frames, "
      << (ec ? 0 : bytes / 1024) << " KiB); open it in a browser" << std::endl;
  return kExitOk;
}

}  // namespace simhuman::app
