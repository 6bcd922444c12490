#pragma once
/// A camera that keeps people in view: it frames a set of bodies and, among candidate
/// directions around them, picks one from which their body points are not hidden behind
/// furniture (rays cast with mj_ray from the camera to each point), preferring a front-side
/// view at a moderate elevation, and glides between choices (CameraSmoother) so the video
/// never jumps.

#include <mujoco/mujoco.h>

#include <Eigen/Core>
#include <vector>

#include "simhuman/render/camera.h"

namespace simhuman::render {

/// Settings of an AutoCamera. Angles in degrees, times in seconds.
struct AutoCameraOptions {
  std::vector<double> elevations_deg = {-12, -22, -35, -50};  ///< candidates (negative: down)
  int azimuth_steps = 12;  ///< candidate azimuths all round, plus the preferred one
  double preferred_elevation_deg = -20;
  /// The preferred view looks at the subject's front from this far to its side (0: face on).
  double preferred_side_deg = 35;
  double margin = 1.3;        ///< FrameBodies margin
  double aspect = 4.0 / 3.0;  ///< image width / height
  double reselect_s = 0.25;   ///< how often the candidates are scored again
  double switch_gain = 0.15;  ///< a new direction must score this much better to be taken
  double smooth_s = 0.6;      ///< CameraSmoother time constant
  double min_camera_height_m = 0.4;
};

/// One candidate's score: larger is better.
struct ViewScore {
  double visible = 0;  ///< weighted fraction of the points seen, 0..1
  double total = 0;    ///< visible, less the penalties for leaving the preferred view
};

/// The camera's position for `spec` (MuJoCo's free camera: it looks along (cos el cos az,
/// cos el sin az, sin el) at lookat from distance_m away).
Eigen::Vector3d CameraPosition(const CameraSpec& spec);

/// The weighted fraction of `points` visible from `spec`: a point is hidden when the ray from
/// the camera to it first meets a geom of a body not marked in `subject` (per body id; the
/// subject's own limbs never hide it) short of the point. `weights` per point (empty: 1 each).
/// Reads d->geom_xpos / geom_xmat (after mj_kinematics).
double VisibleFraction(const mjModel* m, const mjData* d, const CameraSpec& spec,
                       const std::vector<Eigen::Vector3d>& points,
                       const std::vector<double>& weights, const std::vector<char>& subject);

/// Chooses a camera per frame for a video. Not thread-safe; one per video.
class AutoCamera {
 public:
  /// `bodies`: the body ids to frame (all of them stay in the picture); `sites`: the site ids
  /// of the points that should be seen (hands count double); the subject is every body whose
  /// root body is the root of one of `bodies`. Empty `bodies` or bad ids are programming errors.
  AutoCamera(const mjModel* m, std::vector<int> bodies, std::vector<int> sites,
             std::vector<double> site_weights, const AutoCameraOptions& options = {});

  /// The camera for the state in `d` (after mj_kinematics), `dt_s` after the previous frame.
  /// `facing_deg`: the heading the subject faces, about +z (0 = +x); the preferred view looks
  /// at that side.
  CameraSpec Update(const mjData* d, double facing_deg, double dt_s);

  /// The score of the direction in use at the last re-selection.
  const ViewScore& last_score() const { return score_; }

 private:
  ViewScore Score(const mjData* d, const CameraSpec& framing, double az, double el,
                  double facing_deg) const;

  const mjModel* m_;
  std::vector<int> bodies_, sites_;
  std::vector<double> weights_;
  std::vector<char> subject_;
  AutoCameraOptions options_;
  CameraSmoother smoother_;
  bool chosen_ = false;
  double az_ = 0, el_ = 0, since_select_s_ = 0;
  ViewScore score_;
};

}  // namespace simhuman::render
