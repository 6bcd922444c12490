#include "simhuman/app/clip_command.h"

#include <cmath>
#include <filesystem>

#include "simhuman/app/common.h"
#include "simhuman/learn/bvh.h"
#include "simhuman/learn/gait_clip.h"
#include "simhuman/learn/motion_clip.h"

namespace simhuman::app {
namespace {

absl::Status MakeParentDir(const std::string& path) {
  std::filesystem::path parent = std::filesystem::path(path).parent_path();
  if (parent.empty()) return absl::OkStatus();
  return MakeOutputDir(parent.string());
}

void Summary(std::ostream& out, const std::string& cmd, const learn::MotionClip& clip,
             const std::string& path) {
  out << "simhuman clip " << cmd << ": wrote " << path << " (" << clip.frames.size()
      << " frames at " << clip.fps << " fps, " << clip.duration_s() << " s)" << std::endl;
}

}  // namespace

int ClipConvertCommand(const ClipFlags& flags, std::ostream& out, std::ostream& err) {
  if (flags.bvh.empty() || flags.out.empty()) {
    return ReportError(err, "clip convert",
                       absl::InvalidArgumentError("--bvh and --out are required"));
  }
  if (flags.fps < 0 || !std::isfinite(flags.fps) || flags.fps > 1000) {
    return ReportError(err, "clip convert",
                       absl::InvalidArgumentError("--fps must be in (0, 1000] (0: keep)"));
  }
  auto clip = learn::LoadBvhAsClip(flags.bvh);
  if (!clip.ok()) return ReportError(err, "clip convert", clip.status());
  learn::MotionClip result = *std::move(clip);
  if (flags.fps > 0) {
    auto r = learn::ResampleClip(result, flags.fps);
    if (!r.ok()) return ReportError(err, "clip convert", r.status());
    result = *std::move(r);
  }
  absl::Status s = MakeParentDir(flags.out);
  if (s.ok()) s = learn::SaveMotionClip(result, flags.out);
  if (!s.ok()) return ReportError(err, "clip convert", s);
  Summary(out, "convert", result, flags.out);
  return kExitOk;
}

int ClipGaitCommand(const ClipFlags& flags, std::ostream& out, std::ostream& err) {
  if (flags.out.empty()) {
    return ReportError(err, "clip gait", absl::InvalidArgumentError("--out is required"));
  }
  if (!(flags.seconds > 0 && flags.seconds <= 3600)) {
    return ReportError(err, "clip gait",
                       absl::InvalidArgumentError("--seconds " + std::to_string(flags.seconds) +
                                                  " is invalid; valid: (0, 3600]"));
  }
  if (flags.fps < 0 || !std::isfinite(flags.fps) || flags.fps > 1000) {
    return ReportError(err, "clip gait",
                       absl::InvalidArgumentError("--fps must be in (0, 1000] (0: 30 fps)"));
  }
  // with --seconds and --fps checked, GaitClip can only refuse the speed
  learn::GaitClipOptions o;
  o.seconds = flags.seconds;
  o.speed_mps = flags.speed_mps;
  if (flags.fps > 0) o.fps = flags.fps;
  auto clip = learn::GaitClip(o);
  if (!clip.ok()) return ReportError(err, "clip gait", core::Annotate(clip.status(), "--speed"));
  absl::Status s = MakeParentDir(flags.out);
  if (s.ok()) s = learn::SaveMotionClip(*clip, flags.out);
  if (!s.ok()) return ReportError(err, "clip gait", s);
  Summary(out, "gait", *clip, flags.out);
  return kExitOk;
}

}  // namespace simhuman::app
