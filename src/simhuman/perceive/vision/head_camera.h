#pragma once
/// The egocentric camera of DASH (Ye et al. 2021, Section 3.1 and Appendix A.1): an RGB camera at
/// a seated human's eyes that looks at a gaze point (the table region at task planning, the
/// destination while placing). A pinhole model gives the pixel <-> ray maps the vision module
/// needs; the same pose renders through render::OffscreenRenderer as a MuJoCo free camera.

#include <mujoco/mujoco.h>

#include <Eigen/Core>

#include "simhuman/render/camera.h"
#include "simhuman/world/sim_world.h"

namespace simhuman::perceive {

/// A pinhole camera: position, orthonormal axes (forward, right, up; no roll: right is
/// horizontal), vertical field of view and image size. Pixel (u, v): u to the right from the
/// left edge, v down from the top edge, pixel centres at half-integers.
struct PinholeCamera {
  Eigen::Vector3d eye = Eigen::Vector3d::Zero();
  Eigen::Vector3d forward = Eigen::Vector3d::UnitX();
  Eigen::Vector3d right = -Eigen::Vector3d::UnitY();
  Eigen::Vector3d up = Eigen::Vector3d::UnitZ();
  double fovy_deg = 45.0;
  int width = 160, height = 120;

  /// The unit ray (world) through image point (u, v).
  Eigen::Vector3d Ray(double u, double v) const;
  /// The image point of world point `p`; false when `p` is behind the camera.
  bool Project(const Eigen::Vector3d& p, double* u, double* v) const;
  /// A direction (world) in the camera's gravity-aligned frame: x forward along the ground, y
  /// to the left, z up (the frame the vision network predicts in), and back.
  Eigen::Vector3d ToLevel(const Eigen::Vector3d& world_dir) const;
  Eigen::Vector3d FromLevel(const Eigen::Vector3d& level_dir) const;
  /// The camera's pitch (radians, negative looking down).
  double Pitch() const;
  /// The same view as a MuJoCo free camera for render::OffscreenRenderer.
  render::CameraSpec Spec() const;
};

/// A camera at `eye` looking at `target` (not straight up or down: the pitch is clamped to
/// +-85 degrees). Size and field of view as given.
PinholeCamera LookAt(const Eigen::Vector3d& eye, const Eigen::Vector3d& target, double fovy_deg,
                     int width, int height);

/// The eyes of agent `agent` (world): a point on the front of its head sphere, between the eyes,
/// from the head body's pose in `d` (after kinematics).
Eigen::Vector3d EyePosition(const world::SimWorld& world, const mjData* d, int agent);

}  // namespace simhuman::perceive
