#include "simhuman/control/policy/grasp_policy.h"

#include <algorithm>
#include <cmath>
#include <memory>

#include "simhuman/control/manip/scripted_grasp.h"
#include "simhuman/control/policy/policy_net.h"

namespace simhuman::control {

namespace {

manip::GraspPolicyFn Scripted(const mjModel* m, const mjData* d, const manip::GraspIndex& ix,
                              const manip::TabletopGoal& goal,
                              const manip::TabletopOptions& options) {
  return manip::MakeScriptedGrasp(m, d, ix, goal, options);
}

}  // namespace

core::StatusOr<GraspPolicyMaker> LoadGraspPolicy(const std::string& name_or_path) {
  if (name_or_path == "scripted") return GraspPolicyMaker(Scripted);
  const std::string& path = name_or_path;
  SH_ASSIGN_OR_RETURN(LoadedPolicy loaded, LoadPolicyFile(path));
  const bool residual = loaded.meta.task == "grasp-residual";
  SH_RETURN_IF_ERROR(CheckPolicyKind(loaded, path, "grasp", {"grasp", "grasp-residual"},
                                     manip::kGraspObsDim, manip::kGraspActDim, "scripted"));
  const manip::GraspPolicyFn learned = MeanActionFn(std::move(loaded));
  if (!residual) {
    return GraspPolicyMaker([learned](const mjModel*, const mjData*, const manip::GraspIndex&,
                                      const manip::TabletopGoal&,
                                      const manip::TabletopOptions&) { return learned; });
  }
  return GraspPolicyMaker([learned](const mjModel* m, const mjData* d, const manip::GraspIndex& ix,
                                    const manip::TabletopGoal& goal,
                                    const manip::TabletopOptions& options) {
    const manip::GraspPolicyFn base = Scripted(m, d, ix, goal, options);
    return manip::GraspPolicyFn([base, learned](const float* obs, float* act) {
      float b[manip::kGraspActDim], r[manip::kGraspActDim];
      base(obs, b);
      learned(obs, r);
      manip::AddGraspResidual(b, r, act);
    });
  });
}

}  // namespace simhuman::control
