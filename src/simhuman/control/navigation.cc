#include "simhuman/control/navigation.h"

#include <algorithm>
#include <cmath>
#include <iterator>
#include <limits>
#include <queue>

#include "simhuman/core/geometry.h"

namespace simhuman::control {
namespace {

struct Cell {
  int x = 0, y = 0;
};

Cell ToCell(const NavGrid& g, const Eigen::Vector2d& p) {
  int x = static_cast<int>(std::lround((p.x() - g.origin.x()) / g.cell_m));
  int y = static_cast<int>(std::lround((p.y() - g.origin.y()) / g.cell_m));
  return {std::clamp(x, 0, g.nx - 1), std::clamp(y, 0, g.ny - 1)};
}

Eigen::Vector2d CellCentre(const NavGrid& g, int x, int y) {
  return g.origin + g.cell_m * Eigen::Vector2d(x, y);
}

// cost per metre of a cell with clearance `c`
double CellCost(double c, const NavConfig& cfg) {
  if (c < cfg.inside_m) return cfg.inside_cost;
  if (c < cfg.body_radius_m) return cfg.blocked_cost;
  if (c >= cfg.comfort_m) return 1.0;
  double u = (cfg.comfort_m - c) / (cfg.comfort_m - cfg.body_radius_m);
  return 1.0 + cfg.soft_cost * u * u;
}

// cost of the straight segment a-b and the largest cell cost on it, sampled every half cell
void SegmentCost(const NavGrid& g, const NavConfig& cfg, const Eigen::Vector2d& a,
                 const Eigen::Vector2d& b, double* cost, double* worst) {
  double len = (b - a).norm();
  int n = std::max(1, static_cast<int>(std::ceil(len / (0.5 * g.cell_m))));
  *cost = 0;
  *worst = 0;
  for (int i = 0; i < n; ++i) {
    Eigen::Vector2d p = a + (b - a) * ((i + 0.5) / n);
    double c = CellCost(g.ClearanceAt(p), cfg);
    *cost += c * len / n;
    *worst = std::max(*worst, c);
  }
}

}  // namespace

absl::Status NavConfig::Validate() const {
  if (!(cell_m > 0.01 && cell_m <= 1.0)) {
    return absl::InvalidArgumentError("navigation: cell_m must be in (0.01, 1] m");
  }
  if (!(body_radius_m > 0 && comfort_m > body_radius_m)) {
    return absl::InvalidArgumentError("navigation: need 0 < body_radius_m < comfort_m (got " +
                                      std::to_string(body_radius_m) + ", " +
                                      std::to_string(comfort_m) + ")");
  }
  if (!(soft_cost >= 0 && blocked_cost >= 1.0 + soft_cost)) {
    return absl::InvalidArgumentError(
        "navigation: need soft_cost >= 0 and blocked_cost >= 1 + soft_cost");
  }
  if (!(inside_m >= 0 && inside_m <= body_radius_m && inside_cost >= blocked_cost)) {
    return absl::InvalidArgumentError(
        "navigation: need 0 <= inside_m <= body_radius_m and inside_cost >= blocked_cost");
  }
  if (!(margin_m >= 0 && max_extent_m > 0 && max_height_m > min_height_m)) {
    return absl::InvalidArgumentError(
        "navigation: need margin_m >= 0, max_extent_m > 0 and max_height_m > min_height_m");
  }
  return absl::OkStatus();
}

double NavGrid::ClearanceAt(const Eigen::Vector2d& p) const {
  double fx = (p.x() - origin.x()) / cell_m, fy = (p.y() - origin.y()) / cell_m;
  if (fx < -0.5 || fy < -0.5 || fx > nx - 0.5 || fy > ny - 0.5) {
    return std::numeric_limits<double>::infinity();
  }
  Cell c = ToCell(*this, p);
  return Clearance(c.x, c.y);
}

namespace {

// a solid that can block a walker, with a bounding circle for a quick reject
struct Solid {
  const core::Shape* shape;
  const core::Pose* pose;
  Eigen::Vector2d centre;
  double radius;
  double z_lo, z_hi;
};

// the colliding solids between the config's heights; `lo`/`hi` grow to their footprints
std::vector<Solid> CollectSolids(const core::SceneCatalog& scene, const NavConfig& cfg,
                                 Eigen::Vector2d* lo, Eigen::Vector2d* hi) {
  std::vector<Solid> solids;
  for (const core::CatalogObject& o : scene.objects) {
    if (!o.collides) continue;
    for (const core::Shape& s : o.shapes) {
      auto [blo, bhi] = core::ShapesBounds({s});
      // the 8 corners of the local box, in the world
      Eigen::Vector3d wlo = Eigen::Vector3d::Constant(std::numeric_limits<double>::infinity());
      Eigen::Vector3d whi = -wlo;
      for (int k = 0; k < 8; ++k) {
        Eigen::Vector3d c((k & 1) ? bhi.x() : blo.x(), (k & 2) ? bhi.y() : blo.y(),
                          (k & 4) ? bhi.z() : blo.z());
        Eigen::Vector3d w = o.pose.Apply(c);
        wlo = wlo.cwiseMin(w);
        whi = whi.cwiseMax(w);
      }
      if (whi.z() < cfg.min_height_m || wlo.z() > cfg.max_height_m) continue;
      Solid sol{&s,
                &o.pose,
                0.5 * (wlo + whi).head<2>(),
                0.5 * (whi - wlo).head<2>().norm(),
                std::max(wlo.z(), cfg.min_height_m),
                std::min(whi.z(), cfg.max_height_m)};
      solids.push_back(sol);
      *lo = lo->cwiseMin(wlo.head<2>());
      *hi = hi->cwiseMax(whi.head<2>());
    }
  }
  return solids;
}

// horizontal distance from `p` to the solid, probed at a few heights over the span it covers
// (boxes exactly, round solids within a few cm)
double SolidClearance(const Solid& s, const Eigen::Vector2d& p) {
  int n_h = std::max(2, static_cast<int>(std::ceil((s.z_hi - s.z_lo) / 0.25)) + 1);
  double best = std::numeric_limits<double>::infinity();
  for (int k = 0; k < n_h; ++k) {
    double z = s.z_lo + (s.z_hi - s.z_lo) * k / (n_h - 1);
    Eigen::Vector3d q(p.x(), p.y(), z);
    Eigen::Vector3d np = core::NearestPointOnShape(*s.shape, *s.pose, q);
    best = std::min(best, (np - q).head<2>().norm());
  }
  return best;
}

}  // namespace

core::StatusOr<NavGrid> BuildNavGrid(const core::SceneCatalog& scene,
                                     const std::vector<Eigen::Vector2d>& extra,
                                     const NavConfig& cfg) {
  SH_RETURN_IF_ERROR(cfg.Validate());
  Eigen::Vector2d lo = Eigen::Vector2d::Constant(std::numeric_limits<double>::infinity());
  Eigen::Vector2d hi = -lo;
  for (const Eigen::Vector2d& p : extra) {
    if (!p.allFinite()) return absl::InvalidArgumentError("navigation: a non-finite point");
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
  const std::vector<Solid> solids = CollectSolids(scene, cfg, &lo, &hi);
  if (!lo.allFinite()) lo = hi = Eigen::Vector2d::Zero();
  lo -= Eigen::Vector2d::Constant(cfg.margin_m);
  hi += Eigen::Vector2d::Constant(cfg.margin_m);
  if ((hi - lo).maxCoeff() > cfg.max_extent_m) {
    return absl::InvalidArgumentError(
        "navigation: the scene spans " + std::to_string((hi - lo).maxCoeff()) +
        " m; routes are planned over at most max_extent_m = " + std::to_string(cfg.max_extent_m) +
        " m");
  }
  NavGrid g;
  g.origin = lo;
  g.cell_m = cfg.cell_m;
  g.nx = static_cast<int>(std::ceil((hi.x() - lo.x()) / cfg.cell_m)) + 1;
  g.ny = static_cast<int>(std::ceil((hi.y() - lo.y()) / cfg.cell_m)) + 1;
  g.clearance_m.assign(static_cast<size_t>(g.nx) * g.ny, std::numeric_limits<float>::infinity());
  const double reach = cfg.comfort_m + 2 * cfg.cell_m;
  for (const Solid& s : solids) {
    Cell c0 = ToCell(g, s.centre - Eigen::Vector2d::Constant(s.radius + reach));
    Cell c1 = ToCell(g, s.centre + Eigen::Vector2d::Constant(s.radius + reach));
    for (int x = c0.x; x <= c1.x; ++x) {
      for (int y = c0.y; y <= c1.y; ++y) {
        Eigen::Vector2d p = CellCentre(g, x, y);
        if ((p - s.centre).norm() > s.radius + reach) continue;
        float& out = g.clearance_m[static_cast<size_t>(x) * g.ny + y];
        out = std::min(out, static_cast<float>(SolidClearance(s, p)));
      }
    }
  }
  return g;
}

core::StatusOr<NavPath> PlanRoute(const NavGrid& g, const Eigen::Vector2d& start,
                                  const Eigen::Vector2d& goal, const NavConfig& cfg) {
  if (!start.allFinite() || !goal.allFinite()) {
    return absl::InvalidArgumentError("navigation: non-finite start or goal");
  }
  const Cell s = ToCell(g, start), t = ToCell(g, goal);
  const size_t n = static_cast<size_t>(g.nx) * g.ny;
  auto index = [&](int x, int y) { return static_cast<size_t>(x) * g.ny + y; };
  std::vector<double> cost(n, std::numeric_limits<double>::infinity());
  std::vector<int64_t> parent(n, -1);
  std::vector<uint8_t> closed(n, 0);
  using Entry = std::pair<double, size_t>;
  std::priority_queue<Entry, std::vector<Entry>, std::greater<Entry>> open;
  auto h = [&](int x, int y) { return g.cell_m * std::hypot(x - t.x, y - t.y); };
  cost[index(s.x, s.y)] = 0;
  open.push({h(s.x, s.y), index(s.x, s.y)});
  static const int kDx[8] = {1, -1, 0, 0, 1, 1, -1, -1};
  static const int kDy[8] = {0, 0, 1, -1, 1, -1, 1, -1};
  while (!open.empty()) {
    auto [f, i] = open.top();
    open.pop();
    if (closed[i]) continue;
    closed[i] = 1;
    int x = static_cast<int>(i / g.ny), y = static_cast<int>(i % g.ny);
    if (x == t.x && y == t.y) break;
    double ci = CellCost(g.Clearance(x, y), cfg);
    for (int k = 0; k < 8; ++k) {
      int nx = x + kDx[k], ny = y + kDy[k];
      if (nx < 0 || ny < 0 || nx >= g.nx || ny >= g.ny) continue;
      size_t j = index(nx, ny);
      if (closed[j]) continue;
      double step = g.cell_m * (k < 4 ? 1.0 : M_SQRT2);
      double c = cost[i] + step * 0.5 * (ci + CellCost(g.Clearance(nx, ny), cfg));
      if (c < cost[j]) {
        cost[j] = c;
        parent[j] = static_cast<int64_t>(i);
        open.push({c + h(nx, ny), j});
      }
    }
  }
  // cells from goal back to start, then world points with the exact endpoints
  std::vector<Eigen::Vector2d> raw;
  for (int64_t i = static_cast<int64_t>(index(t.x, t.y)); i >= 0; i = parent[i]) {
    raw.push_back(CellCentre(g, static_cast<int>(i / g.ny), static_cast<int>(i % g.ny)));
    if (i == static_cast<int64_t>(index(s.x, s.y))) break;
  }
  std::reverse(raw.begin(), raw.end());
  if (raw.empty()) raw.push_back(start);
  raw.front() = start;
  if (raw.size() == 1) raw.push_back(goal);
  raw.back() = goal;
  // shortcuts: from each kept point, the farthest later point whose straight segment is no
  // costlier per metre than the worst cell of the stretch it replaces
  std::vector<Eigen::Vector2d> pts = {raw.front()};
  size_t i = 0;
  while (i + 1 < raw.size()) {
    size_t best = i + 1;
    double stretch_worst = 0, unused;
    for (size_t j = i + 1; j < raw.size(); ++j) {
      double c, w;
      SegmentCost(g, cfg, raw[j - 1], raw[j], &unused, &w);
      stretch_worst = std::max(stretch_worst, w);
      SegmentCost(g, cfg, raw[i], raw[j], &c, &w);
      if (w <= stretch_worst + 1e-9) best = j;
    }
    pts.push_back(raw[best]);
    i = best;
  }
  NavPath path;
  path.points = pts;
  path.min_clearance_m = std::numeric_limits<double>::infinity();
  for (size_t k = 0; k + 1 < pts.size(); ++k) {
    double len = (pts[k + 1] - pts[k]).norm();
    int m = std::max(1, static_cast<int>(std::ceil(len / (0.5 * g.cell_m))));
    for (int q = 0; q < m; ++q) {
      Eigen::Vector2d p = pts[k] + (pts[k + 1] - pts[k]) * ((q + 0.5) / m);
      if ((p - start).norm() < cfg.body_radius_m || (p - goal).norm() < cfg.body_radius_m) {
        continue;
      }
      double c = g.ClearanceAt(p);
      path.min_clearance_m = std::min(path.min_clearance_m, c);
      if (c < cfg.body_radius_m) path.blocked_m += len / m;
    }
    path.length_m += len;
  }
  return path;
}

core::StatusOr<NavPath> PlanRoute(const core::SceneCatalog& scene, const Eigen::Vector2d& start,
                                  const Eigen::Vector2d& goal, const NavConfig& config) {
  SH_ASSIGN_OR_RETURN(NavGrid grid, BuildNavGrid(scene, {start, goal}, config));
  return PlanRoute(grid, start, goal, config);
}

double PointClearance(const core::SceneCatalog& scene, const Eigen::Vector2d& p,
                      const NavConfig& cfg) {
  Eigen::Vector2d lo = p, hi = p;
  double best = std::numeric_limits<double>::infinity();
  for (const Solid& s : CollectSolids(scene, cfg, &lo, &hi)) {
    if ((p - s.centre).norm() - s.radius > best) continue;
    best = std::min(best, SolidClearance(s, p));
  }
  return best;
}

Eigen::Vector2d ClearStandingSpot(const core::SceneCatalog& scene, const Eigen::Vector2d& point,
                                  const Eigen::Vector2d& centre, double radius_m,
                                  double min_clearance_m, const NavConfig& cfg) {
  Eigen::Vector2d lo = point, hi = point;
  const std::vector<Solid> solids = CollectSolids(scene, cfg, &lo, &hi);
  // clearance capped at min_clearance_m: more room than asked for is not better
  auto room = [&](const Eigen::Vector2d& p) {
    double best = min_clearance_m;
    for (const Solid& s : solids) {
      if ((p - s.centre).norm() - s.radius >= best) continue;
      best = std::min(best, SolidClearance(s, p));
    }
    return best;
  };
  double best_room = room(point);
  if (best_room >= min_clearance_m) return point;
  Eigen::Vector2d best = point;
  double best_dist = 0;
  const double step = kSpotSearchStepM;
  const int n = static_cast<int>(std::ceil(radius_m / step));
  for (int i = -n; i <= n; ++i) {
    for (int j = -n; j <= n; ++j) {
      Eigen::Vector2d p = centre + step * Eigen::Vector2d(i, j);
      if ((p - centre).norm() > radius_m) continue;
      double r = room(p), dist = (p - point).norm();
      if (r > best_room + 1e-6 || (r > best_room - 1e-6 && dist < best_dist)) {
        best = p;
        best_room = r;
        best_dist = dist;
      }
    }
  }
  return best;
}

RouteFollower::RouteFollower(NavPath path, double lookahead_m)
    : path_(std::move(path)), lookahead_m_(lookahead_m) {
  cum_.assign(path_.points.size(), 0.0);
  for (size_t k = 1; k < path_.points.size(); ++k) {
    cum_[k] = cum_[k - 1] + (path_.points[k] - path_.points[k - 1]).norm();
  }
}

Eigen::Vector2d RouteFollower::PointAt(double s, double* heading) const {
  const auto& p = path_.points;
  size_t k = 0;
  while (k + 2 < p.size() && cum_[k + 1] < s) ++k;
  double seg = std::max(1e-9, cum_[k + 1] - cum_[k]);
  double u = std::clamp((s - cum_[k]) / seg, 0.0, 1.0);
  Eigen::Vector2d d = p[k + 1] - p[k];
  *heading = std::atan2(d.y(), d.x());
  return p[k] + u * d;
}

Eigen::Vector2d RouteFollower::PointAhead(double ahead_m) const {
  if (empty()) return Eigen::Vector2d::Zero();
  double heading;
  return PointAt(std::min(progress_m_ + ahead_m, cum_.back()), &heading);
}

RouteFollower::Carrot RouteFollower::Update(const Eigen::Vector2d& w) {
  Carrot out;
  if (empty()) return out;
  const auto& p = path_.points;
  // nearest point of the route at or ahead of the current progress (within a window, so a
  // route that doubles back is not skipped)
  double best_d = std::numeric_limits<double>::infinity(), best_s = progress_m_;
  for (size_t k = 0; k + 1 < p.size(); ++k) {
    if (cum_[k + 1] < progress_m_) continue;
    if (cum_[k] > progress_m_ + 2.0 * lookahead_m_) break;
    Eigen::Vector2d d = p[k + 1] - p[k];
    double len2 = std::max(1e-12, d.squaredNorm());
    double u = std::clamp((w - p[k]).dot(d) / len2, 0.0, 1.0);
    double s = cum_[k] + u * std::sqrt(len2);
    if (s < progress_m_) {
      s = progress_m_;
      u = (s - cum_[k]) / std::sqrt(len2);
    }
    double dist = (w - (p[k] + u * d)).norm();
    if (dist < best_d) {
      best_d = dist;
      best_s = s;
    }
  }
  progress_m_ = best_s;
  out.off_route_m = best_d;
  const double total = cum_.back();
  double s = progress_m_ + lookahead_m_;
  if (s >= total) {
    out.final = true;
    s = total;
    // a corner still ahead (round a chair's back to its front): aim at the corner, not
    // straight at the goal through the furniture; final once past the last corner
    for (size_t k = 1; k + 1 < p.size(); ++k) {
      if (cum_[k] > progress_m_ + kCornerPassedM) {
        out.final = false;
        s = cum_[k];
        break;
      }
    }
  }
  out.point = PointAt(s, &out.heading_rad);
  return out;
}

double WayClearance(const core::SceneCatalog& scene, const NavConfig& config,
                    const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
  const double len = (b - a).norm();
  double least = std::numeric_limits<double>::infinity();
  for (double t = kCarrotSkipM; t <= len; t += kCarrotProbeM) {
    least = std::min(least, PointClearance(scene, a + (b - a) * (t / len), config));
  }
  return least;
}

Eigen::Vector2d ClearCarrot(const core::SceneCatalog& scene, const NavConfig& config,
                            const RouteFollower& follower, const Eigen::Vector2d& here,
                            const Eigen::Vector2d& carrot, double lookahead_m) {
  if (follower.empty()) return carrot;
  // a way with kCarrotClearM of room needs no look at the route (the open floor, most ticks)
  const double way_room = WayClearance(scene, config, here, carrot);
  if (way_room >= kCarrotClearM - kCarrotSlackM) return carrot;
  // as much room as the route itself has there, up to kCarrotClearM
  double route_room = kCarrotClearM;
  for (double s = 0; s <= lookahead_m; s += kCarrotProbeM) {
    route_room = std::min(route_room, PointClearance(scene, follower.PointAhead(s), config));
  }
  const double need = route_room - kCarrotSlackM;
  if (way_room >= need) return carrot;
  for (double ahead : kCarrotFallbackM) {
    const Eigen::Vector2d p = follower.PointAhead(ahead);
    if (WayClearance(scene, config, here, p) >= need) return p;
  }
  return follower.PointAhead(kCarrotFallbackM[std::size(kCarrotFallbackM) - 1]);
}

Eigen::Vector2d SlowForTurn(const RouteFollower& follower, const Eigen::Vector2d& here,
                            const Eigen::Vector2d& carrot, double lookahead_m) {
  if (follower.empty()) return carrot;
  const Eigen::Vector2d way = carrot - here;
  const Eigen::Vector2d beyond = follower.PointAhead(lookahead_m + kTurnSlowLookM) - carrot;
  const double dist = way.norm();
  if (dist <= kTurnSlowMinM || beyond.norm() < 1e-3) return carrot;
  const double bend = core::AngleFromCos(way.normalized().dot(beyond.normalized()));
  if (bend <= kTurnSlowFromRad) return carrot;
  // from the full lead at kTurnSlowFromRad down to kTurnSlowMinM at a right angle
  const double f =
      std::clamp(1.0 - (bend - kTurnSlowFromRad) / (0.5 * M_PI - kTurnSlowFromRad), 0.0, 1.0);
  return here + way * ((kTurnSlowMinM + f * (dist - kTurnSlowMinM)) / dist);
}

}  // namespace simhuman::control
