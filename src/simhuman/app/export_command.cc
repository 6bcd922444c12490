#include "simhuman/app/export_command.h"

#include <cmath>
#include <filesystem>

#include "simhuman/app/common.h"
#include "simhuman/core/json_io.h"
#include "simhuman/eval/replay.h"
#include "simhuman/eval/run_record.h"
#include "simhuman/plan/validate.h"
#include "simhuman/render/bvh_export.h"
#include "simhuman/render/gltf_export.h"

namespace simhuman::app {
namespace {

constexpr char kCommand[] = "export";

absl::Status WriteOutput(const std::string& path, const std::string& bytes) {
  const std::filesystem::path parent = std::filesystem::path(path).parent_path();
  if (!parent.empty()) SH_RETURN_IF_ERROR(MakeOutputDir(parent.string()));
  return core::WriteFileAtomic(path, bytes);
}

render::QposFrames FramesOf(const control::Trajectory& tr) { return {tr.time_s, tr.qpos}; }

// the video and contact sheet of `run`, with its plan's steps as captions
int RenderRun(const ExportRunFlags& flags, const eval::RunRecord& run, std::ostream& out,
              std::ostream& err) {
  if (!run.chain) {
    return ReportError(err, kCommand,
                       absl::NotFoundError("--video/--sheet: run folder '" + flags.run_dir +
                                           "' has no plan.json (its steps are the captions)"));
  }
  const plan::ContactChain* chain = &*run.chain;
  eval::ReplayOptions replay;
  replay.video_path = flags.video;
  replay.sheet_path = flags.sheet;
  replay.auto_camera = !flags.fixed_camera;
  replay.shadows = flags.shadows;
  for (const std::string& path : {flags.video, flags.sheet}) {
    const std::filesystem::path parent = std::filesystem::path(path).parent_path();
    absl::Status st =
        path.empty() || parent.empty() ? absl::OkStatus() : MakeOutputDir(parent.string());
    if (!st.ok()) return ReportError(err, kCommand, st);
  }
  absl::Status st = eval::RenderReplay(*run.world, *chain, run.trajectory, replay);
  if (!st.ok()) return ReportError(err, kCommand, st);
  for (const std::string& path : {flags.video, flags.sheet}) {
    if (!path.empty()) out << "simhuman export: wrote " << path << std::endl;
  }
  return kExitOk;
}

}  // namespace

std::vector<std::string> BvhPaths(const std::string& path, int num_humans) {
  if (num_humans == 1) return {path};
  const std::filesystem::path p(path);
  std::vector<std::string> out;
  for (int k = 0; k < num_humans; ++k) {
    out.push_back(
        (p.parent_path() / (p.stem().string() + "_h" + std::to_string(k) + p.extension().string()))
            .string());
  }
  return out;
}

int ExportRunCommand(const ExportRunFlags& flags, std::ostream& out, std::ostream& err) {
  if (flags.bvh.empty() && flags.gltf.empty() && flags.video.empty() && flags.sheet.empty()) {
    return ReportError(err, kCommand,
                       absl::InvalidArgumentError("nothing to export; give one or more of --bvh "
                                                  "FILE, --gltf FILE.glb, --video FILE.mp4, "
                                                  "--sheet FILE.png"));
  }
  if (flags.fps < 0 || !std::isfinite(flags.fps) || flags.fps > 1000) {
    return ReportError(err, kCommand,
                       absl::InvalidArgumentError("--fps " + std::to_string(flags.fps) +
                                                  " is invalid; valid: (0, 1000], or 0 for the "
                                                  "run's rate"));
  }
  core::StatusOr<eval::RunRecord> run = eval::LoadRunRecord(flags.run_dir);
  if (!run.ok()) return ReportError(err, kCommand, run.status());
  const world::SimWorld& world = *run->world;
  const int humans = world.num_agents();
  if (flags.agent >= humans || flags.agent < -1) {
    return ReportError(err, kCommand,
                       absl::InvalidArgumentError("--agent " + std::to_string(flags.agent) +
                                                  " is not a human of this run; valid: 0.." +
                                                  std::to_string(humans - 1)));
  }
  const double fps = flags.fps > 0 ? flags.fps : run->trajectory.fps;
  const render::QposFrames frames = FramesOf(run->trajectory);
  if (!flags.bvh.empty()) {
    const int first = flags.agent >= 0 ? flags.agent : 0;
    const int n = flags.agent >= 0 ? 1 : humans;
    const std::vector<std::string> paths = BvhPaths(flags.bvh, n);
    for (int k = 0; k < n; ++k) {
      core::StatusOr<std::string> bvh =
          render::AgentBvh(world.model(), world.agent(first + k), frames, fps);
      absl::Status st = bvh.ok() ? WriteOutput(paths[k], *bvh) : bvh.status();
      if (!st.ok()) return ReportError(err, kCommand, core::Annotate(st, paths[k]));
      out << "simhuman export: wrote " << paths[k] << " (human " << first + k << ", " << fps
          << " fps)" << std::endl;
    }
  }
  if (!flags.gltf.empty()) {
    render::GltfOptions options;
    options.fps = fps;
    core::StatusOr<std::string> glb = render::SceneGlb(world.model(), frames, options);
    absl::Status st = glb.ok() ? WriteOutput(flags.gltf, *glb) : glb.status();
    if (!st.ok()) return ReportError(err, kCommand, core::Annotate(st, flags.gltf));
    out << "simhuman export: wrote " << flags.gltf << " (" << glb->size() / 1024 << " KiB, " << fps
        << " fps)" << std::endl;
  }
  if (!flags.video.empty() || !flags.sheet.empty()) {
    const int code = RenderRun(flags, *run, out, err);
    if (code != kExitOk) return code;
  }
  return kExitOk;
}

}  // namespace simhuman::app
