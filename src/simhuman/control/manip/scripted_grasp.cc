#include "simhuman/control/manip/scripted_grasp.h"

#include <algorithm>
#include <cmath>
#include <memory>

#include "simhuman/core/geometry.h"

namespace simhuman::control::manip {

namespace {

// world/hand.h order of the 22 hand joints after the arm's 7: the palm arch, four fingers of
// (abduction, MCP, PIP, DIP), then the thumb's CMC flexion, CMC abduction, MCP flexion, MCP
// abduction and IP
constexpr int kThumbFirst = 17;

// the palm's outward normal, level (the right palm faces its frame's +y, the left its -y)
Eigen::Vector3d PalmNormal(const mjData* d, const GraspIndex& ix) {
  Eigen::Vector3d n(d->xmat[9 * ix.arm.hand_body + 1], d->xmat[9 * ix.arm.hand_body + 4],
                    d->xmat[9 * ix.arm.hand_body + 7]);
  if (!ix.arm.right) n = -n;
  n.z() = 0;
  return n.norm() > 1e-6 ? n.normalized() : n;
}

}  // namespace

GraspPolicyFn MakeScriptedGrasp(const mjModel* m, const mjData* d, const GraspIndex& ix,
                                const TabletopGoal& goal, const TabletopOptions& pipeline,
                                const ScriptedGraspOptions& o) {
  const double grip_z = goal.planned_pos.z() + GripHeightM(goal, pipeline);
  const bool top = TopGrasp(goal, pipeline);
  struct State {
    int step = 0;
    int closing_from = -1;  // the step the palm touched (or the approach ran out)
    double grip_z = 0;      // the palm's height: where the reach left it
    bool have_goal = false;
    bool palm_touched = false;
    double push = 0;             // ScriptedGraspOptions::push_gain's accumulated push (m)
    double last_gap = 0;         // the palm's gap to the object's side at the previous step
    double tilt0 = 0;            // the object's tilt when the grasp began
    double thumb_clear = 0;      // ScriptedGraspOptions::thumb_clear_step_m's accumulated shift
    bool backing_off = false;    // the tilt guard holds the palm back
    Eigen::Vector3d backed_off;  // where: behind the palm as the guard first saw the tilt
    Eigen::Vector3d palm_goal;
    Eigen::Matrix3d hand_rot;  // the hand's rotation as the reach left it
    std::shared_ptr<mjData> scratch;
  };
  auto st = std::make_shared<State>();
  st->scratch.reset(mj_makeData(m), mj_deleteData);
  const double side_behind = PalmBehindM(goal, pipeline);
  return [m, d, &ix, goal, o, st, grip_z, top, side_behind, behind = pipeline.top_palm_behind_m](
             const float* obs, float* act) {
    std::fill(act, act + kGraspActDim, 0.0f);
    float touch[kGraspTouchParts];
    GraspTouch(m, d, ix, goal.object_body, touch);
    const bool palm = touch[0] > 0 || touch[1] > 0;
    const bool touching =
        std::any_of(touch, touch + kGraspTouchParts, [](float t) { return t > 0; });
    const bool newly_touched = palm && !st->palm_touched;
    st->palm_touched = st->palm_touched || palm;
    if (st->closing_from < 0 && (palm || st->step >= o.approach_steps)) {
      st->closing_from = st->step;
    }
    // the palm: to the object's side along its normal, `press_m` into it, by inverse kinematics
    // from the current targets, so the servos' lag does not stall the approach
    const ObjectView seen = ObserveObject(goal, d, false);
    const Eigen::Vector3d& c = seen.centre;
    const Eigen::Vector3d p(d->site_xpos + 3 * ix.arm.palm_site);
    const Eigen::Vector3d n = PalmNormal(d, ix);
    // the reach may take a far object higher than the default grip height
    const Eigen::Map<const Eigen::Matrix<double, 3, 3, Eigen::RowMajor>> hand_rot(
        d->xmat + 9 * ix.arm.hand_body);
    const double tilt = core::AngleFromCos(seen.up.z());
    if (st->step == 0) {
      st->grip_z = std::abs(p.z() - grip_z) < 0.02 ? grip_z : p.z();
      st->hand_rot = hand_rot;
      st->tilt0 = tilt;
    }
    const bool guarding = st->closing_from < 0 || st->step - st->closing_from < o.tilt_guard_steps;
    const bool tipping = guarding && o.tilt_guard_rad > 0 && tilt - st->tilt0 > o.tilt_guard_rad;
    const bool thumb = touch[15] > 0 || touch[16] > 0;
    if (thumb && !st->palm_touched) {
      st->thumb_clear = std::min(st->thumb_clear + o.thumb_clear_step_m, o.thumb_clear_max_m);
    }
    if (!st->have_goal || st->closing_from < 0 || o.press_while_closing) {
      if (top) {
        // down onto the top (the table holds it still), the palm point `behind` back from it
        // along the fingers
        Eigen::Vector3d f(-d->xmat[9 * ix.arm.hand_body + 2], -d->xmat[9 * ix.arm.hand_body + 5],
                          0);
        if (f.norm() > 1e-6) f.normalize();
        st->palm_goal = c - behind * f;
        st->palm_goal.z() = c.z() + goal.half_width_m - o.press_m;
      } else {
        // the palm on the object: no gap, whatever the object's centre and width say (an
        // estimate would not follow an object the palm pushes, and a palm meeting a side at an
        // angle or with its edge never reaches the plane they give: it pushed objects over)
        const double gap =
            (seen.estimated || o.touch_ends_gap) && palm ? 0.0 : (c - p).dot(n) - goal.half_width_m;
        // the push grows while the palm has stalled short of the object, and ends at the touch;
        // after it, the press grows while the closing hand pushes the palm off (repress_*)
        if (newly_touched || (st->palm_touched && o.repress_gain <= 0)) {
          st->push = 0;
        } else if (st->palm_touched) {
          if (!palm && !tipping && st->step - st->closing_from < o.repress_steps) {
            st->push = std::min(st->push + o.repress_gain * std::max(0.0, gap), o.repress_max_m);
          }
        } else if (st->step > 0 && !touching && std::abs(gap - st->last_gap) < o.stall_m) {
          st->push = std::min(st->push + o.push_gain * (gap + o.press_m), o.push_max_m);
        }
        st->last_gap = gap;
        if (tipping && !st->backing_off) st->backed_off = p - n * o.tilt_backoff_m;
        st->backing_off = tipping;
        if (tipping) st->push = 0;
        st->palm_goal =
            tipping ? st->backed_off : Eigen::Vector3d(p + n * (gap + o.press_m + st->push));
        if (o.hold_behind && !st->palm_touched) {
          // along the fingers (level, square to the normal): the object's axis `side_behind`
          // ahead of the palm's centre
          Eigen::Vector3d f(-d->xmat[9 * ix.arm.hand_body + 2], -d->xmat[9 * ix.arm.hand_body + 5],
                            0);
          f -= f.dot(n) * n;
          if (f.norm() > 1e-6) {
            f.normalize();
            const double off = (c - p).dot(f) - side_behind - st->thumb_clear;
            st->palm_goal += f * std::copysign(std::max(0.0, std::abs(off) - o.behind_tol_m), off);
          }
        }
        st->palm_goal.z() = st->grip_z;
      }
      st->have_goal = true;
    }
    Eigen::VectorXd target(ArmChain::kDofs);
    for (int i = 0; i < ArmChain::kDofs; ++i) target[i] = obs[kGraspDofs + ArmChain::kDofs + i];
    PalmPose pose;
    pose.pos = st->palm_goal;
    // the hand keeps the rotation the reach gave it (the measured one would follow every push
    // of a contact and of the object's weight, and the hand would turn away step by step)
    pose.rot = o.hold_rotation ? st->hand_rot : Eigen::Matrix3d(hand_rot);
    mju_copy(st->scratch->qpos, d->qpos, m->nq);
    IkOptions io;
    io.max_iterations = 30;
    io.rot_weight_m = o.ik_rot_weight_m;
    const IkResult r = SolvePalmIk(m, st->scratch.get(), ix.arm, pose, target, target, io);
    for (int i = 0; i < ArmChain::kDofs; ++i) {
      act[i] = static_cast<float>(std::clamp((r.q[i] - target[i]) / kArmStepRad, -1.0, 1.0));
    }
    if (st->closing_from >= 0) {
      // each finger wraps from its base: the MCP flexes until a phalanx touches, the PIP once
      // the proximal phalanx touches (or the MCP is well bent), the DIP once the middle one
      // touches, so the fingertips never curl in under the object and push it out
      const int k = st->step - st->closing_from;
      const float rate = static_cast<float>(o.close_rate);
      if (k >= o.finger_delay_steps) {
        for (int f = 0; f < 4; ++f) {
          const bool prox = touch[2 + 3 * f] > 0, mid = touch[3 + 3 * f] > 0,
                     dist = touch[4 + 3 * f] > 0;
          const int mcp = ArmChain::kDofs + 2 + 4 * f;  // after the palm arch and abduction
          const bool mcp_bent = obs[mcp] > 0.9 * ix.hi[mcp];
          act[mcp] = prox || mid || dist ? o.hold_rate : rate;
          act[mcp + 1] = dist || mid ? o.hold_rate : prox || mcp_bent ? rate : 0.0f;
          act[mcp + 2] = dist                                         ? o.hold_rate
                         : mid || obs[mcp + 1] > 0.9 * ix.hi[mcp + 1] ? rate
                                                                      : 0.0f;
        }
      }
      if (k >= (top ? 0 : o.thumb_delay_steps)) {
        for (int h : {kThumbFirst, kThumbFirst + 2, kThumbFirst + 4}) {
          act[ArmChain::kDofs + h] = touch[15] > 0 || touch[16] > 0 ? o.hold_rate : rate;
        }
      }
    }
    ++st->step;
  };
}

}  // namespace simhuman::control::manip
