#pragma once
/// A pre-flight check of a plan against where the humans start and where its steps take them.
/// Humans walk only in get-close steps, so a contact step on an object out of reach of where the
/// previous steps leave the human cannot succeed; it is rejected up front with a message that
/// says what to change.

#include <vector>

#include "simhuman/core/scene_catalog.h"
#include "simhuman/core/status.h"
#include "simhuman/plan/contact_chain.h"
#include "simhuman/world/scene.h"

namespace simhuman::eval {

/// How far (m, horizontal, times the human's scale) a standing human can reach a part without
/// walking.
inline constexpr double kMaxReachM = 1.0;

/// Checks that every object a human touches is within reach of where it is at that step.
///
/// The check follows each agent through the steps: it starts where the human starts; a step
/// with a get-close pair of the agent leaves it at that pair's plan::StandPoint(); otherwise a
/// step whose pelvis contacts a part (a seat, a mattress) leaves it on that part (its point
/// nearest to where it was); other steps leave it where it was. An object counts as
/// "approached" by agent a once a step holds a get-close pair of a for it (which leaves every
/// other object behind), or a contact pair of a on it that passed this check. For every other
/// step with contact pairs of agent a on an object it has not approached, the step passes when
/// at least one of those pairs' parts is within `max_reach_m` x the human's scale (horizontal
/// distance from where the agent is to the part's nearest point). Not-contact and not-care
/// pairs, and pairs whose target is a body joint, are not checked. Carry steps are not checked
/// (a carry walks its carriers to the object), and count as an approach.
///
/// `chain` must be grounded against `scene` (plan::ValidateAndGround) and `humans` must hold a
/// human for every agent the plan names (scene.num_agents()). Error (InvalidArgument):
///   "<source>: step 4 (/steps/3): object 'bed000' (part 'mattress') is 3.2 m from where step 3
///   leaves human 0, beyond the 1.0 m a human reaches without walking; add a get-close step for
///   'bed000' before step 4 (the human then walks there)"
absl::Status CheckWithinReach(const plan::ContactChain& chain, const core::SceneCatalog& scene,
                              const std::vector<world::HumanSpec>& humans,
                              double max_reach_m = kMaxReachM);

}  // namespace simhuman::eval
