#pragma once
/// The placing stage as a learnable controller. The scripted placing (tabletop_pipeline.h)
/// lowers the held object in segments of `lower_segment_m`; before each segment it turns the
/// object upright and moves its centre of mass over the target, reading the object's pose. A
/// place policy is asked once before each segment (DASH's placing policy reads the object's
/// pose at 20 Hz; ours decides once per segment, every 0.3-0.8 s) and corrects that segment:
/// where over the target the centre of mass is aimed, which way "upright" is, and how fast the
/// segment descends. A zero action is the scripted placing exactly, so a policy trained as this
/// residual (`simhuman train --task place`) starts from the scripted skill.

#include <mujoco/mujoco.h>

#include <Eigen/Core>
#include <functional>

#include "simhuman/control/manip/grasp_task.h"

namespace simhuman::control::manip {

struct TabletopGoal;
struct ObjectView;

/// Observation: the object's centre of mass from the target (3), its base's height above the
/// target (1), its up axis (3), the palm's centre from the object's centre (3), touch per hand
/// part (17, binary), shape one-hot (box, cylinder, sphere), half width and height (2), stacked
/// or not (1), the share of the descent done (1), the object already bearing on its support (1).
inline constexpr int kPlaceObsDim = 3 + 1 + 3 + 3 + kGraspTouchParts + 3 + 2 + 1 + 1 + 1;  // 36
/// Action (each in [-1, 1]): the aim's offset in x and y, the upright direction's tilt about
/// the world's x and y axes, the segment's descent speed (log scale).
inline constexpr int kPlaceActDim = 5;

/// One decision: observation in, action out.
using PlacePolicyFn = std::function<void(const float* obs, float* act)>;

/// A segment's corrections (world frame).
struct PlaceAdjust {
  Eigen::Vector2d aim = Eigen::Vector2d::Zero();   ///< added to the target's x and y (m)
  Eigen::Vector2d tilt = Eigen::Vector2d::Zero();  ///< the goal's up axis turned about x, y (rad)
  double speed_scale = 1;                          ///< the descent speed's factor
};

inline constexpr double kPlaceAimScaleM = 0.015;
inline constexpr double kPlaceTiltScaleRad = 0.05;
inline constexpr double kPlaceSpeedLogScale = 0.4;

/// The corrections an action asks for (entries clipped to [-1, 1]; non-finite ones read as 0).
PlaceAdjust PlaceAdjustFromAction(const float* act);

/// The up axis the alignment turns the object to: +z turned by `adjust.tilt`.
Eigen::Vector3d PlaceUpGoal(const PlaceAdjust& adjust);

/// Writes kPlaceObsDim floats for a place decision: `seen` is how the controllers see the held
/// object (ObserveObject), `lowered_frac` the share of the descent done, `supported` whether it
/// already bears on its support.
void PlaceObservation(const mjModel* m, const mjData* d, const GraspIndex& ix,
                      const TabletopGoal& goal, const ObjectView& seen, double lowered_frac,
                      bool supported, float* obs);

}  // namespace simhuman::control::manip
