#pragma once
/// Agent kinds (embodiments) as data: a registry of the bodies a scene's humans may have, and
/// the world-level spec of one agent (kind, scale, placement). Everything else about an agent
/// (actuator count, joints, body points) is read from its kind and the compiled model, never
/// from a constant that assumes one body.

#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "simhuman/core/scene_catalog.h"
#include "simhuman/core/status.h"
#include "simhuman/world/humanoid.h"

namespace simhuman::world {

/// One agent kind: today the humanoid, with or without dexterous hands (world/humanoid.h).
struct Embodiment {
  std::string name;         ///< e.g. "humanoid", "humanoid_right_hand"
  std::string description;  ///< one line, for `simhuman scenes` and error messages
  bool right_hand = false;  ///< a dexterous right hand instead of the capsule hand
  bool left_hand = false;
  /// Capsule hands grip (HumanoidSpec::grip_n): the largest adhesion force per hand, N; 0: none
  double grip_n = 0;
};

/// The grip of the "humanoid_grip" kind, N per hand (an adult's two-handed hold of a box by its
/// sides presses well over this; our sphere hands have no fingers to curl over the edges).
inline constexpr double kCarryGripN = 100;

/// The name of the default kind: the humanoid with capsule hands.
inline constexpr char kDefaultAgentKind[] = "humanoid";

/// Every registered kind, the default first.
const std::vector<Embodiment>& Embodiments();

/// Names of the registered kinds, for "valid kinds are: ..." messages.
std::vector<std::string> EmbodimentNames();

/// The kind called `name` (exact); InvalidArgument naming it and the valid kinds when unknown.
core::StatusOr<const Embodiment*> FindEmbodiment(std::string_view name);

/// Where and what one agent is: its kind, size and starting placement (standing at (x, y),
/// facing yaw_rad about +z).
struct AgentSpec {
  double x = 0, y = 0, yaw_rad = 0;
  double scale = 1.0;
  std::string kind = kDefaultAgentKind;
  /// Start seated instead of standing: the pelvis origin this high above the floor (m; a seat
  /// top plus SeatedPelvisAboveSeat(scale)), hips and knees flexed 90 degrees (SeatedHinges()).
  /// 0: standing.
  double seated_pelvis_z = 0;
  /// Hold the pelvis where it starts (a weld to the world): the trunk then stays put while
  /// the arms work, as DASH holds its trunk at the table. Off for every walking human.
  bool hold_pelvis = false;
};

/// Height of the pelvis origin above the seat top for a seated humanoid of `scale` (m).
double SeatedPelvisAboveSeat(double scale);

/// The seated pose's non-zero body hinges: {joint name (without prefix), angle in rad}.
const std::vector<std::pair<std::string, double>>& SeatedHinges();

/// The humanoid generator's parameters for agent `index` of kind `kind` (prefix, colour, hands).
/// `kind` must be registered.
HumanoidSpec MakeHumanoidSpec(const Embodiment& kind, double scale, int index);

/// The body points a plan may name for an agent of kind `kind`, and the agent as plans see it.
core::CatalogAgent MakeCatalogAgent(const Embodiment& kind, double scale);

}  // namespace simhuman::world
