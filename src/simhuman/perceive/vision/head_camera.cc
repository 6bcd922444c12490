#include "simhuman/perceive/vision/head_camera.h"

#include <algorithm>
#include <cmath>

namespace simhuman::perceive {

namespace {
constexpr double kDeg = M_PI / 180.0;
// between the eyes in the head body's frame at scale 1: the head sphere's centre is at
// (0.01, 0, 0.16) with radius 0.1; the camera sits just in front of its surface
const Eigen::Vector3d kEyeInHead(0.115, 0.0, 0.17);
}  // namespace

Eigen::Vector3d PinholeCamera::Ray(double u, double v) const {
  const double t = std::tan(0.5 * fovy_deg * kDeg);
  const double aspect = static_cast<double>(width) / height;
  const double x = (2.0 * u / width - 1.0) * t * aspect;
  const double y = (1.0 - 2.0 * v / height) * t;
  return (forward + x * right + y * up).normalized();
}

bool PinholeCamera::Project(const Eigen::Vector3d& p, double* u, double* v) const {
  const Eigen::Vector3d r = p - eye;
  const double z = r.dot(forward);
  if (z <= 1e-6) return false;
  const double t = std::tan(0.5 * fovy_deg * kDeg);
  const double aspect = static_cast<double>(width) / height;
  const double x = r.dot(right) / z / (t * aspect);
  const double y = r.dot(up) / z / t;
  *u = 0.5 * (x + 1.0) * width;
  *v = 0.5 * (1.0 - y) * height;
  return true;
}

Eigen::Vector3d PinholeCamera::ToLevel(const Eigen::Vector3d& w) const {
  const Eigen::Vector3d fx = Eigen::Vector3d(forward.x(), forward.y(), 0).normalized();
  const Eigen::Vector3d fy(-fx.y(), fx.x(), 0);
  return {w.dot(fx), w.dot(fy), w.z()};
}

Eigen::Vector3d PinholeCamera::FromLevel(const Eigen::Vector3d& l) const {
  const Eigen::Vector3d fx = Eigen::Vector3d(forward.x(), forward.y(), 0).normalized();
  const Eigen::Vector3d fy(-fx.y(), fx.x(), 0);
  return l.x() * fx + l.y() * fy + Eigen::Vector3d(0, 0, l.z());
}

double PinholeCamera::Pitch() const { return std::asin(std::clamp(forward.z(), -1.0, 1.0)); }

render::CameraSpec PinholeCamera::Spec() const {
  render::CameraSpec s;
  s.distance_m = 1.0;
  s.lookat = eye + forward * s.distance_m;
  s.azimuth_deg = std::atan2(forward.y(), forward.x()) / kDeg;
  s.elevation_deg = Pitch() / kDeg;
  return s;
}

PinholeCamera LookAt(const Eigen::Vector3d& eye, const Eigen::Vector3d& target, double fovy_deg,
                     int width, int height) {
  PinholeCamera c;
  c.eye = eye;
  c.fovy_deg = fovy_deg;
  c.width = width;
  c.height = height;
  Eigen::Vector3d d = target - eye;
  double yaw = std::atan2(d.y(), d.x());
  if (d.head<2>().norm() < 1e-9) yaw = 0;
  const double pitch = std::clamp(std::atan2(d.z(), d.head<2>().norm()), -85 * kDeg, 85 * kDeg);
  c.forward = Eigen::Vector3d(std::cos(pitch) * std::cos(yaw), std::cos(pitch) * std::sin(yaw),
                              std::sin(pitch));
  c.right = Eigen::Vector3d(std::sin(yaw), -std::cos(yaw), 0);
  c.up = c.right.cross(c.forward);
  return c;
}

Eigen::Vector3d EyePosition(const world::SimWorld& w, const mjData* d, int agent) {
  const world::AgentIndex& ix = w.agent(agent);
  const int b = ix.head_body;
  const Eigen::Map<const Eigen::Matrix<double, 3, 3, Eigen::RowMajor>> R(d->xmat + 9 * b);
  const Eigen::Map<const Eigen::Vector3d> p(d->xpos + 3 * b);
  return p + R * (kEyeInHead * ix.scale);
}

}  // namespace simhuman::perceive
