#include "simhuman/control/policy/grasp_policy.h"

#include <algorithm>
#include <cmath>
#include <memory>

#include "simhuman/control/policy/policy_net.h"

namespace simhuman::control {

core::StatusOr<manip::GraspPolicyFn> LoadGraspPolicy(const std::string& path) {
  SH_ASSIGN_OR_RETURN(LoadedPolicy loaded, LoadPolicyFile(path));
  if (loaded.meta.task != "grasp" || loaded.meta.obs_dim != manip::kGraspObsDim ||
      loaded.meta.act_dim != manip::kGraspActDim) {
    return absl::InvalidArgumentError(
        "grasp policy '" + path + "' is a '" + loaded.meta.task + "' policy with " +
        std::to_string(loaded.meta.obs_dim) + " observations and " +
        std::to_string(loaded.meta.act_dim) + " actions; a grasp policy has " +
        std::to_string(manip::kGraspObsDim) + " and " + std::to_string(manip::kGraspActDim) +
        " (train one with: simhuman train --task grasp)");
  }
  auto policy = std::make_shared<LoadedPolicy>(std::move(loaded));
  return manip::GraspPolicyFn([policy](const float* obs, float* act) {
    std::fill(act, act + manip::kGraspActDim, 0.0f);
    for (int i = 0; i < manip::kGraspObsDim; ++i) {
      if (!std::isfinite(obs[i])) return;
    }
    try {
      torch::NoGradGuard ng;
      torch::Tensor x =
          torch::from_blob(const_cast<float*>(obs), {1, manip::kGraspObsDim}, torch::kFloat32);
      torch::Tensor a = policy->actor->forward(policy->norm.Normalize(x)).contiguous();
      std::copy(a.data_ptr<float>(), a.data_ptr<float>() + manip::kGraspActDim, act);
    } catch (const c10::Error&) {
      std::fill(act, act + manip::kGraspActDim, 0.0f);
    }
  });
}

}  // namespace simhuman::control
