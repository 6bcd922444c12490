#include "simhuman/control/policy/place_policy.h"

#include "simhuman/control/policy/policy_net.h"

namespace simhuman::control {

core::StatusOr<manip::PlacePolicyFn> LoadPlacePolicy(const std::string& name_or_path) {
  if (name_or_path == "scripted") return manip::PlacePolicyFn();
  const std::string& path = name_or_path;
  SH_ASSIGN_OR_RETURN(LoadedPolicy loaded, LoadPolicyFile(path));
  SH_RETURN_IF_ERROR(CheckPolicyKind(loaded, path, "place", {"place"}, manip::kPlaceObsDim,
                                     manip::kPlaceActDim, "scripted"));
  return manip::PlacePolicyFn(MeanActionFn(std::move(loaded)));
}

}  // namespace simhuman::control
