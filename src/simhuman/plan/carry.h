#pragma once
/// Carry steps of a Chain of Contacts: one or more humans carry a movable object (CooHOI). A
/// carry step names the object, its carriers and where the object goes; grounding
/// (GroundCarryStep, called by ValidateAndGround) checks it against the scene, picks each
/// carrier's hold (the object's held points, core::CarryInfo) and writes the carriers' hand
/// contacts into the step's pairs. JSON form: docs/FORMATS.md ("Carry steps"). No MuJoCo here.

#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "simhuman/core/scene_catalog.h"
#include "simhuman/core/status.h"

namespace simhuman::plan {

enum class Direction;  // contact_chain.h
struct ContactChain;

/// What happens to the carried object at the end of the step.
enum class CarryTarget {
  kHold,    ///< no destination: lift it and keep holding it ("pick up the box")
  kFloor,   ///< put it down at a floor point (x, y[, yaw])
  kBeside,  ///< put it down beside another object, on the floor, clear of it
  kHere,    ///< put it down where the carriers stand ("put it down here"); resolved when run
};

/// "hold", "point", "beside", "here".
std::string CarryTargetName(CarryTarget target);

/// Where the carried object goes.
struct CarryDestination {
  CarryTarget kind = CarryTarget::kHold;
  double x_m = 0.0, y_m = 0.0;    ///< kFloor: the object's origin on the floor, world
  std::optional<double> yaw_rad;  ///< kFloor: its final yaw; unset: grounding chooses
  std::string object;             ///< kBeside: the reference object's id
  /// kBeside: the reference's side (front, back, left, right; its own frame); unset: grounding
  /// picks the clear side nearest to the carried object.
  std::optional<Direction> side;
};

/// One carrier: a human and the hold (index into the object's layout for the team's size) it
/// takes; hold -1 = its position in the carrier list.
struct Carrier {
  int agent = 0;
  int hold = -1;
};

/// The carry part of a ContactStep.
struct CarryStep {
  std::string object;             ///< id of the carried object
  std::vector<Carrier> carriers;  ///< at least one; distinct agents
  CarryDestination to;

  /// Set by grounding for kFloor and kBeside: the object's final pose on the floor.
  std::optional<core::Pose> goal;
  /// Set by grounding for kBeside: the side of the reference object it goes to.
  std::optional<Direction> goal_side;

  /// The agents, in carrier order.
  std::vector<int> Agents() const;
};

/// Parses the "carry" value of a simhuman-form step: {"object", "carriers", "to"} where
/// carriers is a list of agent indices or of {"agent", "hold"} and "to" is absent (hold),
/// "here", {"point": [x, y], "yaw_deg"?} or {"beside": id, "side"?}. Errors start with the
/// field's JSON pointer (`where` is the pointer of the "carry" value) and list valid values.
core::StatusOr<CarryStep> ParseCarryJson(const nlohmann::json& j, const std::string& where);

/// The JSON form ParseCarryJson() reads (the request, not the grounded goal).
nlohmann::json CarryToJson(const CarryStep& carry);

/// One line for comparisons and logs: "carry box000 by 0 to beside bed001" (the side only when
/// the plan named it), "... to point (1.5, 2)", "... to here", "... and hold".
std::string CarrySummary(const CarryStep& carry);

/// Checks step `s` of `chain` (which has a carry) against `scene` and grounds it: the object
/// exists and is carryable (core::CarryInfo), carriers are valid distinct agents and at most as
/// many as the object has held points for, its mass is within TeamCapacityKg() of the team,
/// the carriers can stand at the object's stand points, and the destination is on the floor,
/// clear of every other object (and so are the carriers' stand points there). Fills holds,
/// `goal`, `goal_side`, and replaces the step's pairs with each carrier's two hand contacts on
/// its held parts. Then moves the object in `scene` to its goal, so later steps see it there.
/// Errors are InvalidArgument, start with "<source>: <JSON pointer>: " and say which object
/// and why (mass against capacity, the object in the way, the valid agents).
absl::Status GroundCarryStep(ContactChain& chain, int s, core::SceneCatalog& scene);

}  // namespace simhuman::plan
