#include "simhuman/learn/motion_clip.h"

#include <algorithm>
#include <cmath>
#include <nlohmann/json.hpp>

#include "simhuman/core/json_io.h"
#include "simhuman/core/json_reader.h"

namespace simhuman::learn {
namespace {

constexpr double kQuatNormTol = 1e-3;
constexpr double kMaxFps = 1000;
constexpr double kMaxResampledFrames = 1e6;  // 9 h at 30 fps; 280 MB of frames

std::array<double, 4> Slerp(const std::array<double, 4>& a, std::array<double, 4> b, double u) {
  double dot = a[0] * b[0] + a[1] * b[1] + a[2] * b[2] + a[3] * b[3];
  if (dot < 0) {  // the shorter way round
    for (double& v : b) v = -v;
    dot = -dot;
  }
  std::array<double, 4> r;
  if (dot > 0.9995) {
    for (int k = 0; k < 4; ++k) r[k] = a[k] + u * (b[k] - a[k]);
  } else {
    double th = std::acos(std::min(1.0, dot));
    double s = std::sin(th);
    double wa = std::sin((1 - u) * th) / s, wb = std::sin(u * th) / s;
    for (int k = 0; k < 4; ++k) r[k] = wa * a[k] + wb * b[k];
  }
  double n = std::sqrt(r[0] * r[0] + r[1] * r[1] + r[2] * r[2] + r[3] * r[3]);
  for (double& v : r) v /= n;
  return r;
}

// the clip in `j`; errors name the JSON pointer of the culprit
core::StatusOr<MotionClip> ClipFromJson(const nlohmann::json& j) {
  SH_RETURN_IF_ERROR(core::CheckKeys(j, {"format", "fps", "joints", "frames", "source"}, "/"));
  for (const char* k : {"format", "fps", "joints", "frames"}) {
    SH_RETURN_IF_ERROR(core::RequireKey(j, k, "/"));
  }
  SH_RETURN_IF_ERROR(core::ReadName(j.at("format"), "/format", {kClipFormat}, "format").status());
  MotionClip clip;
  SH_ASSIGN_OR_RETURN(
      clip.fps, core::ReadNumber(j.at("fps"), "/fps", core::NumberRange::AboveUpTo(0, kMaxFps)));
  if (j.contains("source")) {
    SH_ASSIGN_OR_RETURN(clip.source, core::ReadString(j.at("source"), "/source"));
  }
  const auto& names = world::HumanoidJointNames();
  SH_ASSIGN_OR_RETURN(std::vector<std::string> joints,
                      core::ReadStrings(j.at("joints"), "/joints"));
  if (joints.size() != names.size()) {
    return core::JsonError("/joints", "expected the " + std::to_string(names.size()) +
                                          " hinge names in actuator order, got an array of " +
                                          std::to_string(joints.size()) +
                                          "; the names are: " + core::JoinNames(names));
  }
  for (size_t k = 0; k < names.size(); ++k) {
    if (joints[k] != names[k]) {
      return core::JsonError(core::JsonPointer("/joints", k),
                             "expected '" + names[k] + "', got '" + joints[k] +
                                 "' (actuator order: " + core::JoinNames(names) + ")");
    }
  }
  const nlohmann::json& jf = j.at("frames");
  if (!jf.is_array() || jf.empty()) {
    return core::JsonError("/frames", "expected a non-empty array of rows");
  }
  clip.frames.resize(jf.size());
  for (size_t f = 0; f < jf.size(); ++f) {
    const std::string at = core::JsonPointer("/frames", f);
    const nlohmann::json& row = jf[f];
    if (!row.is_array() || row.size() != static_cast<size_t>(kClipRowSize)) {
      return core::JsonError(at, "expected an array of " + std::to_string(kClipRowSize) +
                                     " numbers (x y z, qw qx qy qz, 28 angles), got " +
                                     (row.is_array() ? "an array of " + std::to_string(row.size())
                                                     : std::string(row.type_name())));
    }
    SH_ASSIGN_OR_RETURN(auto v, core::ReadFixedNumbers<kClipRowSize>(row, at));
    ClipFrame& fr = clip.frames[f];
    std::copy(v.begin(), v.begin() + 3, fr.root_pos_m.begin());
    std::copy(v.begin() + 3, v.begin() + 7, fr.root_quat_wxyz.begin());
    std::copy(v.begin() + 7, v.end(), fr.q_rad.begin());
    double n = std::sqrt(v[3] * v[3] + v[4] * v[4] + v[5] * v[5] + v[6] * v[6]);
    if (std::abs(n - 1) > kQuatNormTol) {
      return core::JsonError(at, "the root quaternion (entries 3-6) has norm " +
                                     core::FormatNumber(n) + "; it must be a unit quaternion");
    }
  }
  return clip;
}

}  // namespace

absl::Status MotionClip::Validate() const {
  if (!(fps > 0 && fps <= kMaxFps)) {
    return absl::InvalidArgumentError("fps " + std::to_string(fps) + " is outside (0, 1000]");
  }
  if (frames.empty()) return absl::InvalidArgumentError("the clip has no frames");
  for (size_t f = 0; f < frames.size(); ++f) {
    const ClipFrame& fr = frames[f];
    auto finite = [](const auto& a) {
      return std::all_of(a.begin(), a.end(), [](double v) { return std::isfinite(v); });
    };
    if (!finite(fr.root_pos_m) || !finite(fr.root_quat_wxyz) || !finite(fr.q_rad)) {
      return absl::InvalidArgumentError("frame " + std::to_string(f) + ": non-finite number");
    }
    double n = 0;
    for (double v : fr.root_quat_wxyz) n += v * v;
    if (std::abs(std::sqrt(n) - 1) > kQuatNormTol) {
      return absl::InvalidArgumentError("frame " + std::to_string(f) +
                                        ": root quaternion is not a unit quaternion");
    }
  }
  return absl::OkStatus();
}

core::StatusOr<MotionClip> ParseMotionClip(const std::string& json_text, const std::string& where) {
  SH_ASSIGN_OR_RETURN(nlohmann::json j, core::ParseJson(json_text, where));
  core::StatusOr<MotionClip> clip = ClipFromJson(j);
  if (!clip.ok()) return core::Annotate(clip.status(), where);
  return clip;
}

core::StatusOr<MotionClip> LoadMotionClip(const std::string& path) {
  SH_ASSIGN_OR_RETURN(std::string text, core::ReadFile(path));
  return ParseMotionClip(text, path);
}

std::string MotionClipToJson(const MotionClip& clip) {
  nlohmann::json j;
  j["format"] = kClipFormat;
  j["fps"] = clip.fps;
  j["joints"] = world::HumanoidJointNames();
  if (!clip.source.empty()) j["source"] = clip.source;
  nlohmann::json frames = nlohmann::json::array();
  for (const ClipFrame& fr : clip.frames) {
    nlohmann::json row = nlohmann::json::array();
    for (double v : fr.root_pos_m) row.push_back(v);
    for (double v : fr.root_quat_wxyz) row.push_back(v);
    for (double v : fr.q_rad) row.push_back(v);
    frames.push_back(std::move(row));
  }
  j["frames"] = std::move(frames);
  // one frame per line keeps files diffable without the bulk of full indentation
  std::string out = "{\n";
  bool first = true;
  for (const char* k : {"format", "fps", "source", "joints"}) {
    if (!j.contains(k)) continue;
    out += std::string(first ? "" : ",\n") + "  \"" + k + "\": " + j[k].dump();
    first = false;
  }
  out += ",\n  \"frames\": [\n";
  for (size_t f = 0; f < j["frames"].size(); ++f) {
    out += "    " + j["frames"][f].dump() + (f + 1 < j["frames"].size() ? ",\n" : "\n");
  }
  out += "  ]\n}\n";
  return out;
}

absl::Status SaveMotionClip(const MotionClip& clip, const std::string& path) {
  SH_RETURN_IF_ERROR(core::Annotate(clip.Validate(), path));
  return core::WriteFileAtomic(path, MotionClipToJson(clip));
}

ClipFrame SampleClip(const MotionClip& clip, double t_s) {
  const size_t n = clip.frames.size();
  double x = std::clamp(t_s * clip.fps, 0.0, static_cast<double>(n - 1));
  size_t i0 = std::min(static_cast<size_t>(x), n - 1);
  size_t i1 = std::min(i0 + 1, n - 1);
  double u = x - static_cast<double>(i0);
  const ClipFrame &a = clip.frames[i0], &b = clip.frames[i1];
  if (i0 == i1 || u == 0.0) return a;
  ClipFrame r;
  for (int k = 0; k < 3; ++k)
    r.root_pos_m[k] = a.root_pos_m[k] + u * (b.root_pos_m[k] - a.root_pos_m[k]);
  for (int k = 0; k < world::kHumanoidDofs; ++k)
    r.q_rad[k] = a.q_rad[k] + u * (b.q_rad[k] - a.q_rad[k]);
  r.root_quat_wxyz = Slerp(a.root_quat_wxyz, b.root_quat_wxyz, u);
  return r;
}

core::StatusOr<MotionClip> ResampleClip(const MotionClip& clip, double fps) {
  if (!(fps > 0 && fps <= kMaxFps)) {
    return absl::InvalidArgumentError("resample: fps must be in (0, 1000]");
  }
  SH_RETURN_IF_ERROR(clip.Validate());
  MotionClip out;
  out.fps = fps;
  out.source = clip.source;
  const double dur = clip.duration_s();
  // a valid file can last for ages (fps 1e-6): refuse before the count overflows or the
  // frames exhaust memory
  const double count = std::floor(dur * fps + 1e-9) + 1;
  if (!(count <= kMaxResampledFrames)) {
    return absl::InvalidArgumentError("resample: the clip lasts " + core::FormatNumber(dur) +
                                      " s: " + core::FormatNumber(count) + " frames at " +
                                      core::FormatNumber(fps) + " fps, more than " +
                                      core::FormatNumber(kMaxResampledFrames));
  }
  const size_t n = static_cast<size_t>(count);
  out.frames.reserve(n);
  for (size_t i = 0; i < n; ++i) out.frames.push_back(SampleClip(clip, i / fps));
  return out;
}

}  // namespace simhuman::learn
