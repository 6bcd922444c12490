#include "simhuman/core/footprint.h"

#include <algorithm>
#include <cmath>

namespace simhuman::core {

double PoseYaw(const Pose& pose) {
  const Eigen::Vector3d x = pose.quat * Eigen::Vector3d::UnitX();
  if (x.head<2>().norm() < 1e-12) return 0.0;  // +x points straight up or down
  return std::atan2(x.y(), x.x());
}

double FootprintDistance(const CatalogObject& o, const Eigen::Vector2d& p) {
  if (o.shapes.empty()) return std::hypot(p.x() - o.pose.pos.x(), p.y() - o.pose.pos.y());
  const auto [lo, hi] = o.LocalBounds();
  const double yaw = PoseYaw(o.pose);
  const double dx = p.x() - o.pose.pos.x(), dy = p.y() - o.pose.pos.y();
  const double lx = std::cos(yaw) * dx + std::sin(yaw) * dy;
  const double ly = -std::sin(yaw) * dx + std::cos(yaw) * dy;
  const double ex = std::max({lo.x() - lx, 0.0, lx - hi.x()});
  const double ey = std::max({lo.y() - ly, 0.0, ly - hi.y()});
  return std::hypot(ex, ey);
}

}  // namespace simhuman::core
