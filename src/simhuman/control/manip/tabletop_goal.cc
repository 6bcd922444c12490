/// The tabletop pipeline's goal geometry, names and clock (declared in tabletop_pipeline.h).
#include <time.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>

#include "simhuman/control/manip/tabletop_pipeline.h"

namespace simhuman::control::manip {

const char* TabletopStageName(TabletopStage s) {
  switch (s) {
    case TabletopStage::kReach:
      return "reach";
    case TabletopStage::kGrasp:
      return "grasp";
    case TabletopStage::kLift:
      return "lift";
    case TabletopStage::kTransport:
      return "transport";
    case TabletopStage::kPlace:
      return "place";
    case TabletopStage::kRelease:
      return "release";
    case TabletopStage::kSettle:
      return "settle";
    case TabletopStage::kDone:
      return "done";
  }
  return "?";
}

std::vector<std::vector<double>> SeatedRaiseViaRad() {
  return {
      {0.5, 0, 0, 0.4, 0, 0, 0}, {0.5, -0.7, 0, 1.2, 0, -0.8, 0}, {0.3, -0.7, 0, 2.6, 0, -0.8, 0}};
}

std::vector<PalmPose> TransportPalmGoals(const Eigen::Matrix3d& rh, const Eigen::Vector3d& r_obj,
                                         const Eigen::Vector3d& r_palm,
                                         const Eigen::Matrix3d& upright,
                                         const Eigen::Vector3d& base_goal, int turns) {
  std::vector<PalmPose> goals;
  for (int k = 0; k < turns; ++k) {
    const double theta = -M_PI + 2 * M_PI * k / turns;
    const Eigen::Matrix3d r = Eigen::AngleAxisd(theta, Eigen::Vector3d::UnitZ()) * upright * rh;
    goals.push_back({base_goal - r * r_obj + r * r_palm, r, std::nullopt});
  }
  return goals;
}

std::vector<Eigen::VectorXd> RaiseVias(const TabletopOptions& o) {
  std::vector<Eigen::VectorXd> vias;
  for (const std::vector<double>& v : o.raise_via_rad)
    vias.push_back(Eigen::Map<const Eigen::VectorXd>(v.data(), static_cast<int>(v.size())));
  return vias;
}

double GripHeightM(const TabletopGoal& g, const TabletopOptions& o) {
  if (g.grip_height_m >= 0) return g.grip_height_m;
  const double z =
      g.shape == GraspShape::kSphere ? g.half_width_m : g.height_m * o.grip_height_frac;
  return std::clamp(z, o.grip_min_m, o.grip_max_m);
}

double PalmBehindM(const TabletopGoal& g, const TabletopOptions& o) {
  return std::max(o.palm_behind_m, g.half_width_m - o.palm_behind_margin_m);
}

bool TopGrasp(const TabletopGoal& g, const TabletopOptions& o) {
  return o.sphere_top_grasp && g.shape == GraspShape::kSphere;
}

ObjectView ObserveObject(const TabletopGoal& g, const mjData* d, bool held) {
  if (g.observe) return g.observe(d, held);
  ObjectView v;
  const Eigen::Matrix3d r =
      Eigen::Map<const Eigen::Matrix<double, 3, 3, Eigen::RowMajor>>(d->xmat + 9 * g.object_body);
  v.centre = Eigen::Vector3d(d->xipos + 3 * g.object_body);
  v.base = Eigen::Vector3d(d->xpos + 3 * g.object_body);
  v.up = r.col(2);
  v.yaw_rad = std::atan2(r(1, 0), r(0, 0));
  return v;
}

double ThreadCpuSeconds() {
  timespec t{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return t.tv_sec + 1e-9 * t.tv_nsec;
}

}  // namespace simhuman::control::manip
