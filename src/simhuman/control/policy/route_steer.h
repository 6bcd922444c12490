#pragma once
/// Where the walking policy's target goes while a route is followed: the carrot ahead on the
/// route (or, facing far from it, the walker's own spot, to turn there first), then the goal
/// and its heading. The walking controller steers this way in scenes, and the walk task trains
/// on random routes steered the same way, so the policy learns the targets it is given.

#include <Eigen/Core>

#include "simhuman/control/navigation.h"
#include "simhuman/control/policy/walk_task.h"

namespace simhuman::control {

/// On the last stretch the walker faces the goal and turns to its heading within this of it
/// (until pushed twice as far away).
inline constexpr double kFinalTurnM = 0.35;
/// Facing more than this away from the carrot, the walker turns on the spot until within
/// kTurnDoneRad of it, then walks facing the carrot.
inline constexpr double kTurnFirstRad = 1.0;
inline constexpr double kTurnDoneRad = 0.35;

/// The steering's memory between policy steps (one per walk).
struct RouteSteer {
  bool turning = false;     ///< turning on the spot towards the carrot
  bool final_turn = false;  ///< close enough to the goal to turn to its heading

  /// Sets `state`'s target for the walker at `here` facing `yaw` (rad): while `carrot` is not
  /// final, the carrot (turning: `here`) facing the carrot; then `goal`, facing it, and its
  /// heading `goal_yaw` within kFinalTurnM of it.
  void Steer(const Eigen::Vector2d& here, double yaw, const RouteFollower::Carrot& carrot,
             const Eigen::Vector2d& goal, double goal_yaw, WalkState* state);
};

}  // namespace simhuman::control
