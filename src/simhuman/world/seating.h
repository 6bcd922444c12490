#pragma once
/// Humans that start seated: from a scene's human (posture "sit" at a seat) to the simulator's
/// agent placement.

#include <optional>

#include "simhuman/core/scene_catalog.h"
#include "simhuman/core/status.h"
#include "simhuman/world/embodiment.h"
#include "simhuman/world/scene.h"

namespace simhuman::world {

/// The top (world z, metres) of the highest "seat surface" part whose footprint contains the
/// floor point `xy`; nullopt when no seat is there.
std::optional<double> SeatTopUnder(const core::SceneCatalog& scene, const Eigen::Vector2d& xy);

/// The agent placement of scene human `index`: standing where it stands, or, for posture "sit",
/// seated on the seat under its position (hips and knees bent, the pelvis on the seat), with
/// the pelvis held when its kind has a dexterous hand (the tabletop set-up: the trunk is held
/// still, as DASH holds it, while the arm and hand work). Errors (InvalidArgument) name the
/// human's JSON pointer: "sit" with no seat under it, and "lie" starts (not simulated yet).
core::StatusOr<AgentSpec> AgentFromHuman(const HumanSpec& human, int index,
                                         const core::SceneCatalog& scene);

}  // namespace simhuman::world
