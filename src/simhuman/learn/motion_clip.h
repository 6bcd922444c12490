#pragma once
/// Motion clips of our humanoid: a frame rate and, per frame, the root pose and the 28 hinge
/// angles in actuator order (world::HumanoidJointNames()). Torch-free and MuJoCo-free.
///
/// File form ("simhuman-clip-v1", docs/FORMATS.md "Motion clips"): one JSON object
///   {"format": "simhuman-clip-v1", "fps": 30, "joints": [28 names],
///    "frames": [[x, y, z, qw, qx, qy, qz, q_0 ... q_27], ...], "source": "..." (optional)}
/// Positions in metres (world frame, z up), the root quaternion wxyz (MuJoCo order), angles in
/// radians. Loading is strict: unknown keys, a wrong joint list, short rows, non-finite numbers
/// and zero quaternions are errors that name the file and the field or frame.

#include <array>
#include <string>
#include <vector>

#include "simhuman/core/status.h"
#include "simhuman/world/humanoid.h"

namespace simhuman::learn {

inline constexpr char kClipFormat[] = "simhuman-clip-v1";
/// Numbers per frame row: root position (3), root quaternion (4), hinge angles (28).
inline constexpr int kClipRowSize = 7 + world::kHumanoidDofs;

/// One pose of the humanoid.
struct ClipFrame {
  std::array<double, 3> root_pos_m{0, 0, world::kPelvisStandHeight};
  std::array<double, 4> root_quat_wxyz{1, 0, 0, 0};  ///< unit quaternion
  std::array<double, world::kHumanoidDofs> q_rad{};  ///< hinge angles, actuator order
};

/// A clip: frames sampled at `fps`.
struct MotionClip {
  double fps = 30;
  std::vector<ClipFrame> frames;
  std::string source;  ///< free text: where the clip came from (BVH path, generator)

  double duration_s() const { return frames.size() < 2 ? 0.0 : (frames.size() - 1) / fps; }
  /// fps in (0, 1000], at least one frame, finite numbers, unit quaternions (1e-3).
  absl::Status Validate() const;
};

/// Parses a clip from JSON text; `where` (a file name) prefixes every error message.
core::StatusOr<MotionClip> ParseMotionClip(const std::string& json_text, const std::string& where);

/// Reads a clip file. NotFound if it cannot be opened; InvalidArgument naming the file and the
/// field or frame otherwise.
core::StatusOr<MotionClip> LoadMotionClip(const std::string& path);

/// The clip as JSON text (numbers with full double precision, so a round trip is exact).
std::string MotionClipToJson(const MotionClip& clip);

/// Writes the clip to `path` (via a temporary file and a rename). Errors name the file.
absl::Status SaveMotionClip(const MotionClip& clip, const std::string& path);

/// The clip resampled at `fps` over the same duration: linear interpolation of positions and
/// angles, slerp of the root quaternion. InvalidArgument for fps outside (0, 1000] and for
/// more than 1e6 resampled frames (a valid clip at a tiny fps lasts for ages).
core::StatusOr<MotionClip> ResampleClip(const MotionClip& clip, double fps);

/// The pose at time t_s (clamped to the clip), interpolated as in ResampleClip.
ClipFrame SampleClip(const MotionClip& clip, double t_s);

}  // namespace simhuman::learn
