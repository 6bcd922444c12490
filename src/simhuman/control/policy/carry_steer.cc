#include "simhuman/control/policy/carry_steer.h"

#include <cmath>

#include "simhuman/control/policy/walk_task.h"

namespace simhuman::control {
namespace {

// the approach's line (SteerApproach): its start short of the stand point, and how far to the
// side of it the human is taken to be on it (entering, leaving)
constexpr double kApproachLineM = 0.6, kOnLineEnterM = 0.12, kOnLineLeaveM = 0.25;
// the carry aims this far past its stand point, and puts down a box that passes the destination
// at most this far beside it
constexpr double kCarryLeadM = 1.0, kCarryLateralM = 0.2;
constexpr double kCarryReaimM = 0.3;  // the carry's last 0.3 m keep their line (SteerCarry)

}  // namespace

// the stand point `xy`; the walker aims `lead` past it (it stops short of its target)
void SetCarryWalkTarget(CarryState* s, const Eigen::Vector2d& xy, double yaw,
                        const Eigen::Vector2d& lead) {
  s->stand_xy = xy;
  s->walk.target_xy = xy + lead;
  s->walk.target_yaw_rad = yaw;
}

// The approach walks its last stretch straight at the box: away from the line through the stand
// point along the facing direction, it aims at the point of that line kApproachLineM short of the
// stand point first (a walking policy does not side-step a few decimetres into place: it stood
// 0.4 m beside the stand point until the time ran out)
void SteerApproach(const CarryParams& p, const mjData* d, const CarryIndex& ix, CarryState* s) {
  Eigen::Vector3d pos;
  double yaw;
  PelvisPose(d, ix.walk, &pos, &yaw);
  const Eigen::Vector2d f = s->face_dir, left(-f.y(), f.x());
  const Eigen::Vector2d rel = pos.head<2>() - s->stand_xy;
  const double lateral = std::abs(rel.dot(left));
  s->approach_on_line =
      rel.dot(f) < 0.15 && lateral < (s->approach_on_line ? kOnLineLeaveM : kOnLineEnterM);
  if (s->approach_on_line) {
    s->walk.target_xy = s->stand_xy + p.approach_lead_m * f;
    return;
  }
  const Eigen::Vector2d aim = s->stand_xy - kApproachLineM * f;
  const Eigen::Vector2d to = aim - pos.head<2>();
  s->walk.target_xy = aim + (to.norm() > 1e-6 ? p.approach_lead_m * to.normalized() : f);
}

// The carry's walking target, from where the pelvis and the held box are now: the stand point
// puts the box (wherever it is in the arms: it swings 0.3 m to a side) over the destination,
// facing along the way from the box; re-aimed every step (a walker holding a box drifts off a fixed
// line by decimetres in a metre or two), aiming a metre past the stand point so the walk does not
// slow down short of it (a walking policy holding a box shuffles on the spot at slow commands);
// the held box reaching the destination starts the put-down (CarryReachedDestination). Within
// kCarryReaimM of the destination the line is kept, unless the carry is `entering` (then a box
// over the destination keeps the current heading).
void SteerCarry(const Eigen::Vector2d& pelvis, const Eigen::Vector2d& box, bool entering,
                CarryState* s) {
  const Eigen::Vector2d way = s->dest_xy - box;
  if (way.norm() <= kCarryReaimM) {
    if (!entering) return;
  } else {
    s->face_dir = way.normalized();
  }
  const Eigen::Vector2d f = s->face_dir;
  SetCarryWalkTarget(s, s->dest_xy - (box - pelvis), std::atan2(f.y(), f.x()), kCarryLeadM * f);
}

// Whether the held box has come to the destination: within put_down_box_radius_m of it, or
// level with it along the way (the carry's facing direction) and at most kCarryLateralM beside it
bool CarryReachedDestination(const CarryParams& p, const CarryBox& box, const CarryState& s) {
  const Eigen::Vector2d rel = box.pos.head<2>() - s.dest_xy;
  const Eigen::Vector2d f = s.face_dir;
  const double lateral = std::abs(f.x() * rel.y() - f.y() * rel.x());
  return rel.norm() < p.put_down_box_radius_m || (rel.dot(f) > 0 && lateral < kCarryLateralM);
}

}  // namespace simhuman::control
