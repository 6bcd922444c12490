#pragma once
/// `simhuman clip`: motion clips for AMP (docs/FORMATS.md "Motion clips", "BVH import").
///   simhuman clip convert --bvh in.bvh --out out.clip.json [--fps 30]
///   simhuman clip gait --out gait.clip.json [--seconds 10] [--speed 1.0] [--fps 30]

#include <ostream>
#include <string>

namespace simhuman::app {

/// The flags of `simhuman clip convert` and `simhuman clip gait`.
struct ClipFlags {
  std::string bvh;         ///< convert: input BVH file
  std::string out;         ///< output clip file
  double fps = 0;          ///< convert: resample to this rate (0: keep the BVH's); gait: rate
  double seconds = 10;     ///< gait: clip length, s
  double speed_mps = 1.0;  ///< gait: forward speed, m/s
};

/// `clip convert`: reads and retargets a BVH file and writes a clip. Exit codes as `run`.
int ClipConvertCommand(const ClipFlags& flags, std::ostream& out, std::ostream& err);

/// `clip gait`: writes the walking task's reference gait as a kinematic clip.
int ClipGaitCommand(const ClipFlags& flags, std::ostream& out, std::ostream& err);

}  // namespace simhuman::app
