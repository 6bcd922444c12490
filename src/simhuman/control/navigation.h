#pragma once
/// Obstacle-aware routes for the walking skill: a clearance grid over the floor built from the
/// scene catalog's solids, A* on it, a shortcut pass, and a pure-pursuit follower that turns
/// the route into the moving target the walking policy steers to. MuJoCo- and Torch-free.
///
/// Cost model: a cell's clearance is the horizontal distance from its centre to the nearest
/// solid that stands between `min_height_m` and `max_height_m` above the floor. Cells with
/// less clearance than `body_radius_m` cost `blocked_cost` per metre, and `inside_cost` below
/// `inside_m` (finite, so a route always exists: the start or the stand point may lie close to
/// furniture); cells between
/// `body_radius_m` and `comfort_m` cost more the closer they are; free cells cost 1 per metre.
///
/// Thread-safety: pure functions and plain values.

#include <Eigen/Core>
#include <string>
#include <vector>

#include "simhuman/core/scene_catalog.h"
#include "simhuman/core/status.h"

namespace simhuman::control {

/// Grid and cost parameters.
struct NavConfig {
  double cell_m = 0.1;
  double body_radius_m = 0.3;  ///< cells nearer than this to a solid are "blocked"
  double comfort_m = 0.6;      ///< cells nearer than this cost more
  double soft_cost = 4.0;      ///< extra cost per metre at body_radius_m (falls to 0 at comfort_m)
  double blocked_cost = 60.0;  ///< cost per metre through a blocked cell
  /// cells nearer than this to a solid are inside furniture (under a table top, between a
  /// chair's legs) and cost `inside_cost` per metre: a squeeze past a chair beats a walk through
  /// a table
  double inside_m = 0.1;
  double inside_cost = 1000.0;
  double margin_m = 1.5;       ///< the grid reaches this far beyond the objects, start and goal
  double min_height_m = 0.08;  ///< lower solids (rugs, mats) are stepped over
  double max_height_m = 1.8;   ///< higher solids are walked under
  double max_extent_m = 60.0;  ///< refuse grids larger than this on a side

  absl::Status Validate() const;
};

/// A route on the floor (world frame, m), from the start to the goal.
struct NavPath {
  std::vector<Eigen::Vector2d> points;  ///< at least two: start ... goal
  double length_m = 0;
  /// Metres of the route that pass blocked cells, not counting the first and last
  /// `body_radius_m` (which may start or end next to furniture).
  double blocked_m = 0;
  double min_clearance_m = 0;  ///< smallest clearance along the route (same exclusions)
};

/// The clearance grid (exposed for tests and debug images).
struct NavGrid {
  Eigen::Vector2d origin = Eigen::Vector2d::Zero();  ///< centre of cell (0, 0)
  double cell_m = 0.1;
  int nx = 0, ny = 0;
  std::vector<float> clearance_m;  ///< nx * ny, index ix * ny + iy

  float Clearance(int ix, int iy) const { return clearance_m[static_cast<size_t>(ix) * ny + iy]; }
  /// Clearance at a world point (nearest cell; points off the grid are free).
  double ClearanceAt(const Eigen::Vector2d& p) const;
};

/// Builds the clearance grid covering the catalog's colliding objects and `extra` points.
/// Errors: invalid config, a grid larger than max_extent_m.
core::StatusOr<NavGrid> BuildNavGrid(const core::SceneCatalog& scene,
                                     const std::vector<Eigen::Vector2d>& extra,
                                     const NavConfig& config);

/// Cheapest route from `start` to `goal` on `grid`, shortened where a straight segment costs no
/// more than the cells it skips. Errors: non-finite points.
core::StatusOr<NavPath> PlanRoute(const NavGrid& grid, const Eigen::Vector2d& start,
                                  const Eigen::Vector2d& goal, const NavConfig& config);

/// BuildNavGrid + PlanRoute.
core::StatusOr<NavPath> PlanRoute(const core::SceneCatalog& scene, const Eigen::Vector2d& start,
                                  const Eigen::Vector2d& goal, const NavConfig& config = {});

/// Horizontal clearance (m) from `p` to the nearest solid the walker could bump (colliding
/// objects between the config's heights); infinity in an empty scene.
double PointClearance(const core::SceneCatalog& scene, const Eigen::Vector2d& p,
                      const NavConfig& config = {});

/// Grid step (m) of ClearStandingSpot()'s search.
inline constexpr double kSpotSearchStepM = 0.025;

/// A spot to stand at near `point`: `point` itself when it has at least `min_clearance_m` of
/// room (PointClearance), else the spot within `radius_m` of `centre` (searched on a
/// kSpotSearchStepM grid) with the most room up to `min_clearance_m`, the nearest to `point`
/// among equals. E.g. a chair pushed under a table leaves its stand point inside the table:
/// the human stands in the gap instead.
Eigen::Vector2d ClearStandingSpot(const core::SceneCatalog& scene, const Eigen::Vector2d& point,
                                  const Eigen::Vector2d& centre, double radius_m,
                                  double min_clearance_m, const NavConfig& config = {});

/// Within the lookahead of a route's end, the follower aims at the route's next corner until
/// it is this close to it (RouteFollower::Update).
inline constexpr double kCornerPassedM = 0.15;

/// Pure pursuit along a route: the point `lookahead_m` further along the route than the
/// walker's projection on it (near the end: the next corner, then the goal, `final`). Progress
/// only moves forward.
class RouteFollower {
 public:
  RouteFollower() = default;
  RouteFollower(NavPath path, double lookahead_m);
  bool empty() const { return path_.points.size() < 2; }
  const NavPath& path() const { return path_; }

  struct Carrot {
    Eigen::Vector2d point = Eigen::Vector2d::Zero();
    double heading_rad = 0;  ///< direction of the route at the carrot
    bool final = false;      ///< the carrot is the goal (less than lookahead left)
    double off_route_m = 0;  ///< distance from the walker to the route
  };
  /// Updates the progress with the walker at `p` and returns the carrot.
  Carrot Update(const Eigen::Vector2d& p);
  /// The route's point `ahead_m` beyond the walker's progress (at most its end), after Update().
  Eigen::Vector2d PointAhead(double ahead_m) const;

 private:
  Eigen::Vector2d PointAt(double s, double* heading) const;
  NavPath path_;
  std::vector<double> cum_;  ///< arc length at each point
  double lookahead_m_ = 1.2;
  double progress_m_ = 0;
};

/// The walker's carrot leads it by this much on its route (nearer where the way to it has less
/// room, ClearCarrot, or before a turn, SlowForTurn).
inline constexpr double kRouteLookaheadM = 1.2;

/// The carrot is pulled back along the route (to kCarrotFallbackM ahead of the walker's
/// progress, the first with room) when the straight way to it has less clearance than the
/// route's next `lookahead` (up to kCarrotClearM), less kCarrotSlackM; the way is probed every
/// kCarrotProbeM from kCarrotSkipM past the walker (whose own spot may be near furniture).
inline constexpr double kCarrotClearM = 0.3;
inline constexpr double kCarrotSlackM = 0.03;
inline constexpr double kCarrotProbeM = 0.1;
inline constexpr double kCarrotSkipM = 0.2;
inline constexpr double kCarrotFallbackM[] = {0.9, 0.6, 0.4};

/// The least clearance (PointClearance) along the straight way from `a` to `b`, probed every
/// kCarrotProbeM from kCarrotSkipM past `a`; infinity for a way shorter than that.
double WayClearance(const core::SceneCatalog& scene, const NavConfig& config,
                    const Eigen::Vector2d& a, const Eigen::Vector2d& b);

/// `carrot` (from `follower`'s last Update() at `here`), or a nearer point of its route when
/// the straight way to the carrot has less room than the route itself: pure pursuit cuts
/// corners, and round a stool or a bed's corner it cuts through them.
Eigen::Vector2d ClearCarrot(const core::SceneCatalog& scene, const NavConfig& config,
                            const RouteFollower& follower, const Eigen::Vector2d& here,
                            const Eigen::Vector2d& carrot, double lookahead_m = kRouteLookaheadM);

/// People slow down for a turn. Where the route bends more than kTurnSlowFromRad between the
/// way to the carrot and the next kTurnSlowLookM of route beyond it, the carrot comes nearer
/// along the way to it (the walker's speed command falls with the distance to its target), down
/// to kTurnSlowMinM ahead at a right angle or more.
inline constexpr double kTurnSlowFromRad = 0.4;
inline constexpr double kTurnSlowLookM = 1.0;
inline constexpr double kTurnSlowMinM = 0.6;

/// `carrot` (after `follower`'s last Update() at `here`, `lookahead_m` ahead on the route), or
/// a nearer point on the way to it before a bend of the route (kTurnSlowFromRad).
Eigen::Vector2d SlowForTurn(const RouteFollower& follower, const Eigen::Vector2d& here,
                            const Eigen::Vector2d& carrot, double lookahead_m = kRouteLookaheadM);

}  // namespace simhuman::control
