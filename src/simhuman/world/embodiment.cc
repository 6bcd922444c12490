#include "simhuman/world/embodiment.h"

#include <cmath>

#include "simhuman/core/check.h"
#include "simhuman/world/model_builder.h"

namespace simhuman::world {

const std::vector<Embodiment>& Embodiments() {
  static const std::vector<Embodiment> kinds = {
      {kDefaultAgentKind, "the humanoid: 28 body hinges, capsule hands", false, false},
      {"humanoid_right_hand", "the humanoid with a dexterous right hand (7-DoF arm, 22-DoF hand)",
       true, false},
      {"humanoid_hands", "the humanoid with two dexterous hands (7-DoF arms, 22-DoF hands)", true,
       true},
      {"humanoid_grip",
       "the humanoid whose capsule hands grip what they touch (for carrying; up to 100 N per hand)",
       false, false, kCarryGripN},
  };
  return kinds;
}

std::vector<std::string> EmbodimentNames() {
  std::vector<std::string> out;
  for (const Embodiment& e : Embodiments()) out.push_back(e.name);
  return out;
}

core::StatusOr<const Embodiment*> FindEmbodiment(std::string_view name) {
  for (const Embodiment& e : Embodiments()) {
    if (e.name == name) return &e;
  }
  return absl::InvalidArgumentError(
      "unknown agent kind '" + std::string(name) +
      "'; valid agent kinds are: " + core::JoinNames(EmbodimentNames()));
}

HumanoidSpec MakeHumanoidSpec(const Embodiment& kind, double scale, int index) {
  HumanoidSpec spec;
  spec.scale = scale;
  spec.prefix = AgentPrefix(index);
  if (index == 1) spec.rgba = "0.55 0.7 0.85 1";
  if (index == 2) spec.rgba = "0.75 0.8 0.55 1";
  spec.right_hand = kind.right_hand;
  spec.left_hand = kind.left_hand;
  spec.grip_n = kind.grip_n;
  return spec;
}

double SeatedPelvisAboveSeat(double scale) { return 0.12 * scale; }

const std::vector<std::pair<std::string, double>>& SeatedHinges() {
  constexpr double kDeg = M_PI / 180;
  static const std::vector<std::pair<std::string, double>> hinges = {
      {"right_hip_y", 90 * kDeg},
      {"left_hip_y", 90 * kDeg},
      {"right_knee", 90 * kDeg},
      {"left_knee", 90 * kDeg},
      // arms hanging just clear of the seat's sides (straight down they would pass through it)
      {"right_shoulder_x", 12 * kDeg},
      {"left_shoulder_x", 12 * kDeg},
      {"right_elbow", 10 * kDeg},
      {"left_elbow", 10 * kDeg}};
  return hinges;
}

core::CatalogAgent MakeCatalogAgent(const Embodiment& kind, double scale) {
  core::CatalogAgent agent;
  agent.kind = kind.name;
  agent.scale = scale;
  agent.body_points.points.clear();
  for (const BodyPointSite& p : HumanoidBodyPoints(MakeHumanoidSpec(kind, scale, 0))) {
    agent.body_points.points.push_back(p.info);
  }
  return agent;
}

}  // namespace simhuman::world
