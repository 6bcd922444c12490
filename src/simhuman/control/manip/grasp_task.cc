#include "simhuman/control/manip/grasp_task.h"

#include <algorithm>
#include <cmath>

namespace simhuman::control::manip {

core::StatusOr<GraspIndex> MakeGraspIndex(const world::SimWorld& world, int agent, bool right) {
  SH_ASSIGN_OR_RETURN(ArmChain arm, MakeArmChain(world, agent, right));
  const mjModel* m = world.model();
  GraspIndex ix;
  ix.arm = arm;
  for (int i = 0; i < ArmChain::kDofs; ++i) {
    ix.qpos[i] = arm.qpos[i];
    ix.actuator[i] = arm.actuator[i];
    ix.lo[i] = arm.lo[i];
    ix.hi[i] = arm.hi[i];
  }
  for (int k = 0; k < world::kHandFingerDofs; ++k) {
    const int a = arm.finger_actuators[k];
    if (a < 0) return absl::InternalError("a finger actuator is missing");
    const int j = m->actuator_trnid[2 * a];
    const int i = ArmChain::kDofs + k;
    ix.qpos[i] = m->jnt_qposadr[j];
    ix.actuator[i] = a;
    ix.lo[i] = m->jnt_range[2 * j];
    ix.hi[i] = m->jnt_range[2 * j + 1];
  }
  const std::string side = right ? "right_" : "left_";
  const std::string p = world::AgentPrefix(agent) + side;
  ix.touch_of_geom.assign(m->ngeom, -1);
  const std::vector<std::string>& parts = world::HandTouchParts();
  if (static_cast<int>(parts.size()) != kGraspTouchParts) {
    return absl::InternalError("the hand's touch parts changed; update kGraspTouchParts");
  }
  for (int t = 0; t < kGraspTouchParts; ++t) {
    const int g = mj_name2id(m, mjOBJ_GEOM, (p + parts[t] + "_geom").c_str());
    if (g < 0) return absl::InternalError("touch geom missing: " + p + parts[t]);
    ix.touch_of_geom[g] = t;
  }
  for (int k = 0; k < 5; ++k) {
    ix.tip_site[k] = mj_name2id(m, mjOBJ_SITE, (p + world::HandTipSites()[k]).c_str());
    if (ix.tip_site[k] < 0) return absl::InternalError("fingertip site missing");
  }
  ix.shoulder_site = world.agent(agent).site[static_cast<int>(
      right ? core::BodyJoint::kRightShoulder : core::BodyJoint::kLeftShoulder)];
  return ix;
}

void SetOpenHand(const GraspIndex& ix, mjData* d) {
  for (int k = ArmChain::kDofs; k < kGraspDofs; ++k) d->qpos[ix.qpos[k]] = 0;
  // the thumb (world/hand.h order: after the palm arch and the four fingers' 16) opened into a
  // C across from the fingers: out of the palm's way, its pad facing the object's near side
  // (CMC flexion, CMC abduction, MCP flexion, MCP abduction, IP; degrees)
  constexpr double thumb_deg[5] = {40, -20, 40, 0, 40};
  for (int k = 0; k < 5; ++k) {
    const int i = ArmChain::kDofs + 17 + k;
    d->qpos[ix.qpos[i]] = std::clamp(thumb_deg[k] * M_PI / 180, ix.lo[i], ix.hi[i]);
  }
}

void SetClawHand(const GraspIndex& ix, mjData* d) {
  // world/hand.h order after the arm: palm arch, then (abduction, MCP, PIP, DIP) per finger
  // (index, middle, ring, little; positive abduction toward the little finger), then the thumb
  // (CMC flexion, CMC abduction, MCP flexion, MCP abduction, IP); degrees
  constexpr double deg[22] = {10, -15, 25, 25, 10, 0,  25, 25,  10, 8, 25,
                              25, 10,  18, 25, 25, 10, 40, -20, 40, 0, 40};
  for (int k = 0; k < 22; ++k) {
    const int i = ArmChain::kDofs + k;
    d->qpos[ix.qpos[i]] = std::clamp(deg[k] * M_PI / 180, ix.lo[i], ix.hi[i]);
  }
}

void HoldCurrentPose(const mjData* d, const GraspIndex& ix, GraspState* s) {
  for (int i = 0; i < kGraspDofs; ++i) s->target[i] = d->qpos[ix.qpos[i]];
}

void GraspTouch(const mjModel* m, const mjData* d, const GraspIndex& ix, int object_body,
                float* out) {
  std::fill(out, out + kGraspTouchParts, 0.0f);
  for (int c = 0; c < d->ncon; ++c) {
    const int g1 = d->contact[c].geom1, g2 = d->contact[c].geom2;
    if (m->geom_bodyid[g1] == object_body && ix.touch_of_geom[g2] >= 0) {
      out[ix.touch_of_geom[g2]] = 1.0f;
    } else if (m->geom_bodyid[g2] == object_body && ix.touch_of_geom[g1] >= 0) {
      out[ix.touch_of_geom[g1]] = 1.0f;
    }
  }
}

void GraspObservation(const mjModel* m, const mjData* d, const GraspIndex& ix, const GraspState& s,
                      float* obs) {
  float* o = obs;
  for (int i = 0; i < kGraspDofs; ++i) *o++ = static_cast<float>(d->qpos[ix.qpos[i]]);
  for (int i = 0; i < ArmChain::kDofs; ++i) {
    *o++ = static_cast<float>(0.1 * d->qvel[ix.arm.dof[i]]);
  }
  for (int i = 0; i < kGraspDofs; ++i) *o++ = static_cast<float>(s.target[i]);
  GraspTouch(m, d, ix, s.object_body, o);
  o += kGraspTouchParts;
  const mjtNum* sh = d->site_xpos + 3 * ix.shoulder_site;
  for (int k = 0; k < 3; ++k) *o++ = static_cast<float>(s.task_pos[k] - sh[k]);
  for (int k = 0; k < 3; ++k) *o++ = static_cast<int>(s.shape) == k ? 1.0f : 0.0f;
}

void ApplyGraspAction(const GraspIndex& ix, const float* action, GraspState* s) {
  for (int i = 0; i < kGraspDofs; ++i) {
    const double a = std::clamp(static_cast<double>(action[i]), -1.0, 1.0);
    if (!std::isfinite(a)) continue;
    const double step = i < ArmChain::kDofs ? kArmStepRad : kFingerStepRad;
    s->target[i] = std::clamp(s->target[i] + step * a, ix.lo[i], ix.hi[i]);
  }
}

void WriteGraspCtrl(const mjModel* m, mjData* d, const GraspIndex& ix, const GraspState& s) {
  for (int i = 0; i < kGraspDofs; ++i) {
    const int a = ix.actuator[i];
    double u = s.target[i];
    if (i < ArmChain::kDofs) {
      // gravity and Coriolis feed-forward through the position servo
      const double kp = m->actuator_gainprm[mjNGAIN * a];
      u += d->qfrc_bias[ix.arm.dof[i]] / kp;
    }
    d->ctrl[a] = u;
  }
}

void AddGraspResidual(const float* base, const float* residual, float* out) {
  for (int i = 0; i < kGraspActDim; ++i) {
    const float r = std::isfinite(residual[i]) ? residual[i] : 0.0f;
    out[i] = std::clamp(base[i] + static_cast<float>(kGraspResidualScale) * r, -1.0f, 1.0f);
  }
}

}  // namespace simhuman::control::manip
