#pragma once
/// The tabletop pipeline's placing stage by name: the training-free scripted placing, or a place
/// policy file (`simhuman train --task place`: corrections to the scripted placing's segments,
/// control/manip/place_task.h; the policy's mean action for each observation).

#include <string>

#include "simhuman/control/manip/place_task.h"
#include "simhuman/core/status.h"

namespace simhuman::control {

/// "scripted" (an empty function: the pipeline's own placing), or the path of a policy file or
/// training checkpoint of the place task. Errors (InvalidArgument / NotFound) name the file and
/// what is wrong: missing, not a policy archive, another task's policy, other sizes. The policy
/// is not thread-safe: load one per thread. A non-finite observation gets a zero action.
core::StatusOr<manip::PlacePolicyFn> LoadPlacePolicy(const std::string& name_or_path);

}  // namespace simhuman::control
