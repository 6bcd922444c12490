#pragma once
/// BVH motion capture files (CMU-style: HIERARCHY/ROOT/JOINT/End Site/OFFSET/CHANNELS, then
/// MOTION/Frames/Frame Time and one line of channel values per frame) and their retargeting
/// onto our humanoid as a MotionClip. Torch-free; retargeting compiles the humanoid model
/// (MuJoCo) to read its hinge axes and ranges.
///
/// Mapping, frames and limits are documented in docs/FORMATS.md ("BVH import").

#include <Eigen/Core>
#include <string>
#include <vector>

#include "simhuman/core/status.h"
#include "simhuman/learn/motion_clip.h"

namespace simhuman::learn {

/// One BVH channel.
enum class BvhChannel { kXpos, kYpos, kZpos, kXrot, kYrot, kZrot };

/// A joint (or an End Site: no channels, name "<parent>/End Site").
struct BvhJoint {
  std::string name;
  int parent = -1;  ///< index into BvhMotion::joints, -1 for the root
  Eigen::Vector3d offset = Eigen::Vector3d::Zero();  ///< file units, parent frame
  std::vector<BvhChannel> channels;                  ///< in file order
  int first_channel = 0;                             ///< index of the first channel in a frame row
  bool end_site = false;
};

/// A parsed BVH file. Rotation channels are in degrees; a joint's local rotation is the
/// product of its rotation channels in file order (R = R_ch1 * R_ch2 * R_ch3).
struct BvhMotion {
  std::vector<BvhJoint> joints;  ///< root first, parents before children
  int num_channels = 0;
  double frame_time_s = 0;
  std::vector<std::vector<double>> frames;  ///< [frame][channel]
};

/// Parses BVH text. Errors are InvalidArgument "where:line: what" (unexpected token, a bad
/// channel name or count, a frame line with the wrong number of values, a missing Frames or
/// Frame Time, fewer frame lines than announced).
core::StatusOr<BvhMotion> ParseBvh(const std::string& text, const std::string& where);

/// Reads and parses a BVH file (NotFound if it cannot be read).
core::StatusOr<BvhMotion> LoadBvh(const std::string& path);

/// Retargets BVH motion onto our humanoid (scale 1): body rotations from the BVH global
/// rotations corrected for the rest pose (a T-pose's horizontal arms become our hanging arms
/// abducted 90 degrees), decomposed into our hinge axes and clipped to the joint ranges; the
/// root scaled by our standing pelvis height over the BVH's rest hip height, with the first
/// frame's horizontal position moved to the origin; the BVH's up axis (from the rest skeleton)
/// becomes z. Errors name `bvh.where` joints that are missing (listing accepted names).
core::StatusOr<MotionClip> RetargetBvh(const BvhMotion& bvh, const std::string& where);

/// LoadBvh + RetargetBvh; the clip's source is the path.
core::StatusOr<MotionClip> LoadBvhAsClip(const std::string& path);

/// A clip from a file: ".bvh" (any case) is retargeted, anything else is read as a clip file.
core::StatusOr<MotionClip> LoadAnyClip(const std::string& path);

}  // namespace simhuman::learn
