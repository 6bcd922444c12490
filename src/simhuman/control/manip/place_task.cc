#include "simhuman/control/manip/place_task.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>

#include "simhuman/control/manip/tabletop_pipeline.h"

namespace simhuman::control::manip {

namespace {
double Clipped(float a) {
  return std::isfinite(a) ? std::clamp(static_cast<double>(a), -1.0, 1.0) : 0.0;
}
}  // namespace

PlaceAdjust PlaceAdjustFromAction(const float* act) {
  PlaceAdjust p;
  p.aim = kPlaceAimScaleM * Eigen::Vector2d(Clipped(act[0]), Clipped(act[1]));
  p.tilt = kPlaceTiltScaleRad * Eigen::Vector2d(Clipped(act[2]), Clipped(act[3]));
  p.speed_scale = std::exp(kPlaceSpeedLogScale * Clipped(act[4]));
  return p;
}

Eigen::Vector3d PlaceUpGoal(const PlaceAdjust& a) {
  if (a.tilt.isZero()) return Eigen::Vector3d::UnitZ();
  return (Eigen::AngleAxisd(a.tilt.x(), Eigen::Vector3d::UnitX()) *
          Eigen::AngleAxisd(a.tilt.y(), Eigen::Vector3d::UnitY()))
      .toRotationMatrix()
      .col(2);
}

void PlaceObservation(const mjModel* m, const mjData* d, const GraspIndex& ix,
                      const TabletopGoal& goal, const ObjectView& seen, double lowered_frac,
                      bool supported, float* obs) {
  int k = 0;
  auto put = [&](double v) { obs[k++] = static_cast<float>(v); };
  const Eigen::Vector3d from_target = seen.centre - goal.target;
  for (int j = 0; j < 3; ++j) put(from_target[j]);
  put(seen.base.z() - goal.target.z());
  for (int j = 0; j < 3; ++j) put(seen.up[j]);
  const Eigen::Vector3d palm(d->site_xpos + 3 * ix.arm.palm_site);
  for (int j = 0; j < 3; ++j) put(palm[j] - seen.centre[j]);
  float touch[kGraspTouchParts];
  GraspTouch(m, d, ix, goal.object_body, touch);
  for (float t : touch) put(t > 0 ? 1 : 0);
  put(goal.shape == GraspShape::kBox);
  put(goal.shape == GraspShape::kCylinder);
  put(goal.shape == GraspShape::kSphere);
  put(goal.half_width_m);
  put(goal.height_m);
  put(goal.support_body >= 0);
  put(lowered_frac);
  put(supported);
}

}  // namespace simhuman::control::manip
