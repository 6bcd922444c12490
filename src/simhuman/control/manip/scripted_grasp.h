#pragma once
/// A training-free grasp for the pipeline's grasp stage, the baseline a learned policy is
/// measured against: the palm closes in on the object's side by inverse kinematics until it
/// touches, then the four fingers flex and the thumb opposes them (as in the shared notes'
/// model-based prototype, which held 57 % of objects through a lift).

#include "simhuman/control/manip/tabletop_pipeline.h"

namespace simhuman::control::manip {

/// The scripted grasp of `goal`'s object by arm `ix` in the simulation `m`/`d` (read at each
/// call; the pipeline steps `d`). The function keeps its own scratch data and step count; one
/// per episode.
GraspPolicyFn MakeScriptedGrasp(const mjModel* m, const mjData* d, const GraspIndex& ix,
                                const TabletopGoal& goal);

}  // namespace simhuman::control::manip
