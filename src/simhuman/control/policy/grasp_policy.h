#pragma once
/// A trained grasp policy (`simhuman train --task grasp`) as the tabletop pipeline's grasp
/// stage: the policy's mean action for each observation (control/manip/grasp_task.h).

#include <string>

#include "simhuman/control/manip/tabletop_pipeline.h"
#include "simhuman/core/status.h"

namespace simhuman::control {

/// Loads `path` (a policy file or a training checkpoint of the grasp task). Errors
/// (InvalidArgument / NotFound) name the file and what is wrong: missing, not a policy archive,
/// another task's policy, other observation or action sizes. The returned function is not
/// thread-safe; it writes zeros for a non-finite observation.
core::StatusOr<manip::GraspPolicyFn> LoadGraspPolicy(const std::string& path);

}  // namespace simhuman::control
