#pragma once
/// Joint-space paths for the arm's transition stages (DASH Appendix A.2.2): a polyline of joint
/// vectors, arc-length interpolation, straight-segment validity checks at a fixed joint
/// resolution, and the random shortcutting pass of Hauser and Ng-Thow-Hing (2010) that shortens
/// a planner's path. Independent of MuJoCo and OMPL: validity is a caller's function.
///
/// Distances are Euclidean in joint space (rad for hinges); "arc length" is the sum of the
/// Euclidean lengths of the segments. Thread-safety: pure functions and plain values; a
/// validity function is called only from the calling thread.

#include <Eigen/Core>
#include <cstdint>
#include <functional>
#include <vector>

#include "simhuman/core/rng.h"
#include "simhuman/core/status.h"

namespace simhuman::control::manip {

/// Whether a joint vector is allowed (collision-free, within limits, ...). Called many times;
/// must be deterministic for a given input.
using ValidityFn = std::function<bool(const Eigen::VectorXd&)>;

/// A path in joint space: waypoints joined by straight segments. All waypoints have the same
/// size (the number of joints); an empty path has no waypoints.
struct JointPath {
  std::vector<Eigen::VectorXd> waypoints;

  /// Number of waypoints.
  int size() const { return static_cast<int>(waypoints.size()); }
  /// Number of joints (0 for an empty path).
  int num_dofs() const { return waypoints.empty() ? 0 : static_cast<int>(waypoints[0].size()); }
  /// Total arc length (rad), 0 for fewer than two waypoints.
  double Length() const;
};

/// Cumulative arc lengths: entry i is the length from waypoint 0 to waypoint i (size() entries;
/// entry 0 is 0).
std::vector<double> CumulativeLengths(const JointPath& path);

/// The point at arc length `s` (rad), clamped to [0, Length()]. Aborts on an empty path (a
/// bug). `cumulative` may pass CumulativeLengths(path) to avoid recomputing it.
Eigen::VectorXd PointAt(const JointPath& path, double s,
                        const std::vector<double>* cumulative = nullptr);

/// Index of the segment (waypoint i to i+1) holding arc length `s`, in [0, size() - 2]; 0 for
/// paths with fewer than two waypoints. Zero-length segments are skipped where possible.
int SegmentAt(const std::vector<double>& cumulative, double s);

/// Whether the straight segment from `a` to `b` is valid: checks `b` and then interior states
/// so that consecutive checked states differ by at most `resolution_rad` in every joint (so
/// every point of the segment lies within resolution_rad / 2 per joint of a checked state; an
/// obstacle inflated by that margin is never touched). `a` is assumed valid and not checked.
/// Interior states are checked in bisection order, which finds collisions early.
/// `resolution_rad` must be > 0 (a bug otherwise).
bool SegmentValid(const Eigen::VectorXd& a, const Eigen::VectorXd& b, const ValidityFn& valid,
                  double resolution_rad);

/// Whether every waypoint and every segment of `path` is valid at `resolution_rad` (the first
/// waypoint included). False for an empty path.
bool PathValid(const JointPath& path, const ValidityFn& valid, double resolution_rad);

/// Options of ShortcutPath.
struct ShortcutOptions {
  int iterations = 50;           ///< random shortcut attempts
  double resolution_rad = 0.02;  ///< segment check resolution (see SegmentValid)
  /// share of the attempts that are partial: only one random joint is interpolated between the
  /// two points, the others keep their course (Geraerts and Overmars 2007); these remove the
  /// random excursions of joints that do not matter for the way around an obstacle
  double partial_fraction = 0.5;
  /// an attempt is kept only when it shortens the path by more than this (rad)
  double min_gain_rad = 1e-6;

  /// InvalidArgument naming the field when out of range.
  absl::Status Validate() const;
};

/// Shortens a valid path by random shortcuts (Hauser and Ng-Thow-Hing 2010): picks two arc
/// lengths s1 < s2 uniformly, and when the straight segment between the path's points there is
/// valid and shorter, replaces the part in between with it; a share of the attempts are partial
/// shortcuts (one joint, see ShortcutOptions::partial_fraction). Finishes with a deterministic pass
/// that drops each interior waypoint whose neighbours see each other, and removes repeated
/// waypoints. Endpoints are kept exactly. Draws only from `rng` (same seed, same result).
/// The input should be valid at the same resolution; the output's new segments are checked.
/// Errors: invalid options, waypoints of different sizes or non-finite values.
core::StatusOr<JointPath> ShortcutPath(const JointPath& path, const ValidityFn& valid,
                                       const ShortcutOptions& options, core::Rng& rng);

/// Checks that `path` has at least one waypoint, all of size `num_dofs` (any size when
/// num_dofs < 0) and finite. InvalidArgument naming the waypoint and joint otherwise.
absl::Status CheckPath(const JointPath& path, int num_dofs = -1);

}  // namespace simhuman::control::manip
