#pragma once
/// A pre-flight check of a plan against where the humans start. Walking is not implemented yet,
/// so a plan whose first contact with an object needs the human to cross the room cannot
/// succeed; it is rejected up front with a message that says what to change.

#include <vector>

#include "simhuman/core/scene_catalog.h"
#include "simhuman/core/status.h"
#include "simhuman/plan/contact_chain.h"
#include "simhuman/world/scene.h"

namespace simhuman::eval {

/// How far (m, horizontal, times the human's scale) a standing human can reach a part without
/// walking.
inline constexpr double kMaxReachM = 1.0;

/// Checks that every object a human first touches is within reach of its start.
///
/// Going through the steps in order, an object counts as "approached" by agent a once a step
/// holds a get-close pair of a for it, or a contact pair of a on it that passed this check.
/// For every other step with contact pairs of agent a on an object it has not approached, the
/// step passes when at least one of those pairs' parts is within `max_reach_m` x the human's
/// scale (horizontal distance from the human's start position to the part's nearest point).
/// Not-contact and not-care pairs, and pairs whose target is a body joint, are not checked.
/// Carry steps are not checked (a carry walks its carriers to the object), and count as an
/// approach.
///
/// `chain` must be grounded against `scene` (plan::ValidateAndGround) and `humans` must hold a
/// human for every agent the plan names (scene.num_agents()). Error (InvalidArgument):
///   "<source>: step 2 (/steps/1): object 'bed000' (part 'mattress') is 3.2 m from human 0 and
///   no get-close step precedes step 2; walking is not implemented yet: start the human within
///   1.0 m of it, or add a get-close step for 'bed000' before step 2"
absl::Status CheckWithinReach(const plan::ContactChain& chain, const core::SceneCatalog& scene,
                              const std::vector<world::HumanSpec>& humans,
                              double max_reach_m = kMaxReachM);

}  // namespace simhuman::eval
