#include "simhuman/control/policy/place_policy.h"

#include "simhuman/control/policy/policy_net.h"

namespace simhuman::control {

core::StatusOr<manip::PlacePolicyFn> LoadPlacePolicy(const std::string& name_or_path) {
  if (name_or_path == "scripted") return manip::PlacePolicyFn();
  const std::string& path = name_or_path;
  SH_ASSIGN_OR_RETURN(LoadedPolicy loaded, LoadPolicyFile(path));
  if (loaded.meta.task != "place" || loaded.meta.obs_dim != manip::kPlaceObsDim ||
      loaded.meta.act_dim != manip::kPlaceActDim) {
    return absl::InvalidArgumentError(
        "place policy '" + path + "' is a '" + loaded.meta.task + "' policy with " +
        std::to_string(loaded.meta.obs_dim) + " observations and " +
        std::to_string(loaded.meta.act_dim) + " actions; a place policy has " +
        std::to_string(manip::kPlaceObsDim) + " and " + std::to_string(manip::kPlaceActDim) +
        " (train one with: simhuman train --task place), or use 'scripted'");
  }
  return manip::PlacePolicyFn(MeanActionFn(std::move(loaded)));
}

}  // namespace simhuman::control
