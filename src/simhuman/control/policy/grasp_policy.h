#pragma once
/// The tabletop pipeline's grasp stage by name: the training-free scripted grasp
/// (control/manip/scripted_grasp.h) or a trained policy file (`simhuman train --task grasp`: the
/// policy's mean action for each observation, control/manip/grasp_task.h; `--task
/// grasp-residual`: the scripted grasp's action plus kGraspResidualScale times the policy's).

#include <functional>
#include <string>

#include "simhuman/control/manip/tabletop_pipeline.h"
#include "simhuman/core/status.h"

namespace simhuman::control {

/// Makes one episode's grasp policy for `goal` in `m`/`d` (the scripted grasp keeps per-episode
/// state, so each episode needs a new one).
using GraspPolicyMaker = std::function<manip::GraspPolicyFn(
    const mjModel* m, const mjData* d, const manip::GraspIndex& ix, const manip::TabletopGoal& goal,
    const manip::TabletopOptions& options)>;

/// "scripted", or the path of a policy file or training checkpoint of the grasp or
/// grasp-residual task. Errors (InvalidArgument / NotFound) name the file and what is wrong:
/// missing, not a policy archive, another task's policy, other observation or action sizes. The
/// policies made are not thread-safe; a learned one writes zeros for a non-finite observation.
core::StatusOr<GraspPolicyMaker> LoadGraspPolicy(const std::string& name_or_path);

}  // namespace simhuman::control
