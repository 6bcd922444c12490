#include "simhuman/core/body_joint.h"

#include <cctype>

namespace simhuman::core {
namespace {
constexpr std::array<std::string_view, kNumBodyJoints> kNames = {
    "pelvis",    "torso",          "head",        "left shoulder", "left elbow",
    "left hand", "right shoulder", "right elbow", "right hand",    "left hip",
    "left knee", "left foot",      "right hip",   "right knee",    "right foot"};
}  // namespace

std::string_view BodyJointName(BodyJoint joint) { return kNames[static_cast<int>(joint)]; }

std::optional<BodyJoint> ParseBodyJoint(std::string_view name) {
  std::string norm;
  for (char c : name) {
    norm += (c == '_') ? ' ' : static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  }
  for (int i = 0; i < kNumBodyJoints; ++i) {
    if (kNames[i] == norm) return static_cast<BodyJoint>(i);
  }
  return std::nullopt;
}

std::vector<std::string> BodyJointNames() {
  return std::vector<std::string>(kNames.begin(), kNames.end());
}

std::array<BodyJoint, kNumBodyJoints> AllBodyJoints() {
  std::array<BodyJoint, kNumBodyJoints> out{};
  for (int i = 0; i < kNumBodyJoints; ++i) out[i] = static_cast<BodyJoint>(i);
  return out;
}

}  // namespace simhuman::core
