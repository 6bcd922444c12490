#include "simhuman/control/manip/scripted_grasp.h"

#include <algorithm>
#include <memory>

namespace simhuman::control::manip {

GraspPolicyFn MakeScriptedGrasp(const mjModel* m, const mjData* d, const GraspIndex& ix,
                                const TabletopGoal& goal) {
  struct State {
    int step = 0;
    int closing_from = -1;  // the step the palm touched (or the approach ran out)
    std::shared_ptr<mjData> scratch;
  };
  auto st = std::make_shared<State>();
  st->scratch.reset(mj_makeData(m), mj_deleteData);
  return [m, d, &ix, goal, st](const float* obs, float* act) {
    std::fill(act, act + kGraspActDim, 0.0f);
    float touch[kGraspTouchParts];
    GraspTouch(m, d, ix, goal.object_body, touch);
    const bool palm = touch[0] > 0 || touch[1] > 0;
    if (st->closing_from < 0 && (palm || st->step >= 24)) st->closing_from = st->step;
    if (st->closing_from < 0) {
      // the palm toward the object's axis, level, until it touches
      const Eigen::Vector3d c(d->xipos + 3 * goal.object_body);
      const Eigen::Vector3d p(d->site_xpos + 3 * ix.arm.palm_site);
      Eigen::Vector3d to = c - p;
      to.z() = 0;
      PalmPose pose;
      pose.pos = p + to.normalized() *
                         std::min(0.01, std::max(0.0, to.norm() - goal.half_width_m + 0.005));
      pose.rot = Eigen::Map<const Eigen::Matrix<double, 3, 3, Eigen::RowMajor>>(
          d->xmat + 9 * ix.arm.hand_body);
      mju_copy(st->scratch->qpos, d->qpos, m->nq);
      const Eigen::VectorXd q = ix.arm.Get(d);
      IkOptions io;
      io.max_iterations = 30;
      const IkResult r = SolvePalmIk(m, st->scratch.get(), ix.arm, pose, q, q, io);
      for (int i = 0; i < ArmChain::kDofs; ++i) {
        const double target = obs[kGraspDofs + ArmChain::kDofs + i];
        act[i] = static_cast<float>(std::clamp((r.q[i] - target) / kArmStepRad, -1.0, 1.0));
      }
    } else {
      // fingers first, then the thumb (0.25 s later); finger abduction stays
      const int k = st->step - st->closing_from;
      for (int i = ArmChain::kDofs; i < kGraspActDim; ++i) {
        const int h = i - ArmChain::kDofs;  // world/hand.h order after the arm's three
        const bool thumb = h >= 17;
        const bool abduction = !thumb && h >= 1 && (h - 1) % 4 == 0;
        if (abduction || h == 20) continue;
        act[i] = thumb ? (k >= 10 ? 0.6f : 0.0f) : 0.6f;
      }
    }
    ++st->step;
  };
}

}  // namespace simhuman::control::manip
