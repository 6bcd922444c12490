#include "simhuman/core/body_joint.h"

#include "simhuman/core/scene_catalog.h"

namespace simhuman::core {
namespace {
constexpr std::array<std::string_view, kNumBodyJoints> kNames = {
    "pelvis",    "torso",          "head",        "left shoulder", "left elbow",
    "left hand", "right shoulder", "right elbow", "right hand",    "left hip",
    "left knee", "left foot",      "right hip",   "right knee",    "right foot"};

// the one canonical form of names (scene_catalog.h), digits kept: "Right_Palm" -> "right palm"
std::string Canonical(std::string_view name) { return NormalizeName(name, TrailingDigits::kKeep); }
}  // namespace

std::string_view BodyJointName(BodyJoint joint) {
  const int i = static_cast<int>(joint);
  return i >= 0 && i < kNumBodyJoints ? kNames[i] : std::string_view("extra point");
}

std::optional<BodyJoint> ParseBodyJoint(std::string_view name) {
  const std::string norm = Canonical(name);
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

std::optional<BodyJoint> BodyPointCatalog::Find(std::string_view name) const {
  const std::string norm = Canonical(name);
  for (int i = 0; i < size(); ++i) {
    if (Canonical(points[i].name) == norm) return static_cast<BodyJoint>(i);
  }
  for (int i = 0; i < size(); ++i) {
    for (const std::string& a : points[i].aliases) {
      if (Canonical(a) == norm) return static_cast<BodyJoint>(i);
    }
  }
  return std::nullopt;
}

std::string BodyPointCatalog::Name(BodyJoint id) const {
  if (!Contains(id)) return "point " + std::to_string(static_cast<int>(id));
  return points[static_cast<int>(id)].name;
}

std::vector<std::string> BodyPointCatalog::Names() const {
  std::vector<std::string> out;
  for (const BodyPointInfo& p : points) out.push_back(p.name);
  return out;
}

BodyPointCatalog StandardBodyPointCatalog() {
  BodyPointCatalog c;
  for (std::string_view n : kNames) c.points.push_back({std::string(n), {}});
  return c;
}

}  // namespace simhuman::core
