#include "simhuman/control/policy/route_steer.h"

#include <cmath>

#include "simhuman/core/geometry.h"

namespace simhuman::control {

void RouteSteer::Steer(const Eigen::Vector2d& here, double yaw, const RouteFollower::Carrot& carrot,
                       const Eigen::Vector2d& goal, double goal_yaw, WalkState* state) {
  if (!carrot.final) {
    const Eigen::Vector2d way = carrot.point - here;
    const double bearing = std::atan2(way.y(), way.x());
    const double off = std::abs(core::WrapAngle(bearing - yaw));
    if (!turning && off > kTurnFirstRad) turning = true;
    if (turning && off < kTurnDoneRad) turning = false;
    // face the carrot (not the route's heading there: a walk that starts within the short step
    // range keeps its heading, and would walk sideways into furniture beside the route);
    // turning, the target is the walker's own place, wherever the turn has moved it
    state->target_xy = turning ? here : carrot.point;
    state->target_yaw_rad = bearing;
    return;
  }
  turning = false;
  // the last stretch: walk forwards to the point and turn to the final heading only there (the
  // policy is poor at walking backwards, which a walk point "back to the seat" would ask for)
  const Eigen::Vector2d to = goal - here;
  const double dist = to.norm();
  if (dist < kFinalTurnM) final_turn = true;
  if (dist > 2.0 * kFinalTurnM) final_turn = false;
  state->target_xy = goal;
  state->target_yaw_rad = final_turn ? goal_yaw : std::atan2(to.y(), to.x());
}

}  // namespace simhuman::control
