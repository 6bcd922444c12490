#include "simhuman/control/policy/carry_mpc.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "simhuman/control/rollout.h"
#include "simhuman/world/sim_world.h"

namespace simhuman::control {
namespace {

// Box lowest corner height wanted at phase `s` (m): on the floor until the rise, then rising to
// 0.3 m by the end of the lift, and held at least that high while carrying.
double WantedBoxLow(const CarryState& s) {
  if (s.phase == CarryPhase::kCarry) return 0.3;
  if (s.phase != CarryPhase::kLift) return -1;
  const double rise = LiftRiseStartSeconds();
  if (s.phase_time_s <= rise) return -1;
  return 0.3 * std::min(1.0, (s.phase_time_s - rise) / (kLiftSeconds - rise));
}

}  // namespace

CarryMpc::CarryMpc(const mjModel* m, const CarryIndex& ix, const CarryParams& p, int box_geom,
                   const CarryMpcOptions& o)
    : m_(m), ix_(ix), p_(p), box_geom_(box_geom), o_(o), rng_(o.seed) {
  d_ = mj_makeData(m_);
  scratch_ = mj_makeData(m_);
  best_.assign(std::max(2, o_.knots), {});
}

CarryMpc::~CarryMpc() {
  mj_deleteData(d_);
  mj_deleteData(scratch_);
}

void CarryMpc::ActionAt(const Knots& k, int step, int steps, float* a) const {
  const double u = steps <= 1 ? 0.0 : static_cast<double>(step) / (steps - 1);
  const double x = u * (k.size() - 1);
  const int i = std::min(static_cast<int>(x), static_cast<int>(k.size()) - 2);
  const double f = x - i;
  for (int j = 0; j < kCarryActDim; ++j) {
    a[j] = static_cast<float>((1 - f) * k[i][j] + f * k[i + 1][j]);
  }
}

double CarryMpc::Rollout(const mjData* start, const CarryState& s0, const Knots& k,
                         double* box_low) {
  mjData* d = d_;
  CopyRolloutStart(m_, start, d);
  CarryState s = s0;
  const world::AgentIndex& a = ix_.walk.agent;
  const double dt = kWalkSubsteps * m_->opt.timestep;
  const int steps = std::max(1, static_cast<int>(std::lround(o_.horizon_s / dt)));
  const int lf = ix_.walk.left_foot_geom, rf = ix_.walk.right_foot_geom;
  const int head = a.site[static_cast<int>(core::BodyJoint::kHead)];
  const double body_mass = m_->body_subtreemass[a.pelvis_body];
  const double box_mass = m_->body_mass[m_->geom_bodyid[box_geom_]];
  std::array<float, kCarryActDim> act{};
  double ctrl[kWalkActDim], ref[kWalkActDim];
  double cost = 0;
  Eigen::Vector3d com_prev = Eigen::Vector3d::Zero();
  CarryBox box;
  for (int h = 0; h < steps; ++h) {
    ActionAt(k, h, steps, act.data());
    CarryTargets(ix_, s, act.data(), ctrl);
    SetCarryGrip(ix_, s, d);
    for (int sub = 0; sub < kWalkSubsteps; ++sub) {
      for (int j = 0; j < kWalkActDim; ++j) d->ctrl[a.actuator[j]] = ctrl[j];
      mj_step(m_, d);
    }
    if (!world::AllFinite(d->qpos, m_->nq) || !world::AllFinite(d->qvel, m_->nv)) {
      return std::numeric_limits<double>::infinity();
    }
    box = ReadCarryBox(m_, d, box_geom_);
    const bool was_holding = CarryHandsOnBox(s);
    UpdateCarry(p_, m_, scratch_, d, ix_, box, &s);
    CarryReference(s, ref);
    double c = 0;
    double track = 0;
    for (int j = 0; j < kWalkActDim; ++j) {
      const double e = d->qpos[a.hinge_qpos[j]] - ref[j];
      track += e * e;
    }
    c += o_.w_track * track;
    // balance of the human and, once it is off the floor, the box
    const double low = BoxLowestZ(box);
    Eigen::Vector3d com(d->subtree_com + 3 * a.pelvis_body);
    if (low > 0.02) com = (body_mass * com + box_mass * box.pos) / (body_mass + box_mass);
    if (h > 0) {
      const Eigen::Vector3d v = (com - com_prev) / dt;
      const Eigen::Vector2d cp = (com + v * std::sqrt(std::max(com.z(), 0.1) / 9.81)).head<2>();
      const Eigen::Vector2d mid(0.5 * (d->geom_xpos[3 * lf] + d->geom_xpos[3 * rf]),
                                0.5 * (d->geom_xpos[3 * lf + 1] + d->geom_xpos[3 * rf + 1]));
      const double off = (cp - mid).norm();
      const double out = std::max(0.0, off - 0.1);
      c += o_.w_balance * (SmoothL1(off, 0.05) + 200.0 * out * out);
    }
    com_prev = com;
    // the hands on their held points while the phase holds the box
    // (from the squat on: the hands should be at the faces before the squeeze begins)
    if (was_holding || (s.phase == CarryPhase::kLift && s.phase_time_s > 0.6)) {
      Eigen::Vector3d held_l, held_r;
      CarryHeldPoints(s, box, &held_l, &held_r);
      const Eigen::Vector3d hl(d->site_xpos + 3 * ix_.left_hand_site);
      const Eigen::Vector3d hr(d->site_xpos + 3 * ix_.right_hand_site);
      c += o_.w_hands *
           (SmoothL1((hl - held_l).norm(), 0.03) + SmoothL1((hr - held_r).norm(), 0.03));
    }
    const double wanted = WantedBoxLow(s);
    if (wanted > 0) c += o_.w_box * std::max(0.0, wanted - low);
    c += o_.w_tilt * (1.0 - std::clamp(box.rot(2, 2), -1.0, 1.0)) *
         (s.phase == CarryPhase::kApproach ? 0.0 : 1.0);
    // trunk and falls
    const Eigen::Vector3d pelvis(d->xpos + 3 * a.pelvis_body);
    const Eigen::Vector3d head_p(d->site_xpos + 3 * head);
    const Eigen::Vector3d trunk = (head_p - pelvis).normalized();
    c += o_.w_upright * (1.0 - trunk.z());
    c += o_.w_fall * std::max(0.0, 0.9 - head_p.z());
    c += o_.w_fall * std::max(0.0, s.poses.squat_pelvis_z - 0.12 - pelvis.z());
    if (have_feet0_ && s.phase == CarryPhase::kLift) {
      const Eigen::Vector2d fl(d->geom_xpos[3 * lf], d->geom_xpos[3 * lf + 1]);
      const Eigen::Vector2d fr(d->geom_xpos[3 * rf], d->geom_xpos[3 * rf + 1]);
      c += o_.w_feet *
           (SmoothL1((fl - feet0_[0]).norm(), 0.02) + SmoothL1((fr - feet0_[1]).norm(), 0.02));
    }
    double asq = 0;
    for (float x : act) asq += x * x;
    c += o_.w_action * asq;
    cost += c * (h == steps - 1 ? 3.0 : 1.0);
  }
  *box_low = BoxLowestZ(box);
  return cost * dt;
}

void CarryMpc::Act(const mjData* d, const CarryState& s, float* action) {
  const double dt = kWalkSubsteps * m_->opt.timestep;
  const int nk = static_cast<int>(best_.size());
  if (!have_feet0_ && s.phase == CarryPhase::kLift) {
    const int lf = ix_.walk.left_foot_geom, rf = ix_.walk.right_foot_geom;
    feet0_[0] = Eigen::Vector2d(d->geom_xpos[3 * lf], d->geom_xpos[3 * lf + 1]);
    feet0_[1] = Eigen::Vector2d(d->geom_xpos[3 * rf], d->geom_xpos[3 * rf + 1]);
    have_feet0_ = true;
  }
  // shift the last best spline by one control step
  Knots shifted(nk);
  for (int i = 0; i < nk; ++i) {
    const double t = static_cast<double>(i) / (nk - 1) * o_.horizon_s + dt;
    const double x = std::min(t / o_.horizon_s, 1.0) * (nk - 1);
    const int lo = std::min(static_cast<int>(x), nk - 2);
    const double f = x - lo;
    for (int j = 0; j < kCarryActDim; ++j) {
      shifted[i][j] = static_cast<float>((1 - f) * best_[lo][j] + f * best_[lo + 1][j]);
    }
  }
  double best_cost = std::numeric_limits<double>::infinity();
  Knots best = shifted, cand(nk);
  const float clip = static_cast<float>(kWalkActionClip);
  for (int c = 0; c < o_.samples; ++c) {
    if (c == 0) {
      cand = shifted;
    } else if (c == 1) {
      for (auto& kn : cand) kn.fill(0.f);
    } else {
      for (int i = 0; i < nk; ++i) {
        for (int j = 0; j < kCarryActDim; ++j) {
          const float v = shifted[i][j] + static_cast<float>(rng_.Normal(o_.sigma));
          cand[i][j] = std::clamp(v, -clip, clip);
        }
      }
    }
    double low = 0;
    const double cost = Rollout(d, s, cand, &low);
    if (cost < best_cost) {
      best_cost = cost;
      best = cand;
      last_box_low_ = low;
    }
  }
  best_ = best;
  last_cost_ = best_cost;
  ++iteration_;
  std::copy(best_[0].begin(), best_[0].end(), action);
}

}  // namespace simhuman::control
