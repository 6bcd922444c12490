#pragma once
/// Free cameras for offscreen rendering: a plain spec, framing a set of bodies, and smoothing
/// over frames so videos do not shake.

#include <mujoco/mujoco.h>

#include <Eigen/Core>
#include <vector>

namespace simhuman::render {

/// A free (orbit) camera, as MuJoCo's mjCAMERA_FREE: it looks at `lookat` from `distance_m`
/// away, from the direction given by azimuth (degrees, about world +z; 0 looks along +x, 90
/// along +y) and elevation (degrees; negative looks down). The vertical field of view is the
/// model's m->vis.global.fovy.
struct CameraSpec {
  Eigen::Vector3d lookat = Eigen::Vector3d::Zero();  // world frame, metres
  double distance_m = 3.0;
  double azimuth_deg = 90.0;
  double elevation_deg = -20.0;
};

/// Copies `spec` into a MuJoCo free camera.
void ToMjvCamera(const CameraSpec& spec, mjvCamera* cam);

/// Frames the given bodies so they fill the view: the camera looks at the centre of their
/// geoms' bounding box, from a distance at which the box's bounding sphere fits both the
/// vertical and the horizontal field of view (fovy from m->vis.global.fovy; `aspect` is
/// width / height of the image). `margin` scales the distance (1.0 tight, 1.2 leaves ~20%
/// room). Bodies without geoms count as their origin; planes (infinite) are ignored. An empty
/// `body_ids` frames all bodies except the world. Reads d->xpos, d->geom_xpos (run
/// mj_kinematics or mj_forward first). Body ids out of range or margin <= 0 are programming
/// errors and abort.
CameraSpec FrameBodies(const mjModel* m, const mjData* d, const std::vector<int>& body_ids,
                       double azimuth_deg, double elevation_deg, double margin,
                       double aspect = 1.0);

/// Low-pass filters a camera over frames (first-order, time constant `time_constant_s`), so a
/// camera that follows a moving human glides instead of shaking. Azimuth is unwrapped (going
/// from 179 to -179 degrees moves 2 degrees). Not thread-safe; one per video.
class CameraSmoother {
 public:
  /// `time_constant_s` > 0: the time to cover ~63% of a step change. 0 disables smoothing.
  explicit CameraSmoother(double time_constant_s = 0.5);

  /// Moves the smoothed camera towards `target` for a frame interval `dt_s` and returns it.
  /// The first call (and the first after Reset) returns `target` unchanged.
  CameraSpec Update(const CameraSpec& target, double dt_s);

  /// Forgets the state: the next Update snaps to its target.
  void Reset() { initialized_ = false; }

 private:
  double time_constant_s_;
  bool initialized_ = false;
  CameraSpec state_;
};

}  // namespace simhuman::render
