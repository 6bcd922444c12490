#include "simhuman/control/navigation.h"

#include <gtest/gtest.h>

#include <cmath>

namespace simhuman::control {
namespace {

// a box solid of half-extents (hx, hy, hz) standing on the floor at (x, y)
core::CatalogObject Block(const std::string& id, double x, double y, double hx, double hy,
                          double hz = 0.4) {
  core::CatalogObject o;
  o.id = id;
  o.type = "table";
  o.pose = core::Pose::FromYaw(Eigen::Vector3d(x, y, 0), 0.0);
  core::Shape s;
  s.kind = core::ShapeKind::kBox;
  s.pose.pos = Eigen::Vector3d(0, 0, hz);
  s.size = Eigen::Vector3d(hx, hy, hz);
  o.shapes.push_back(s);
  return o;
}

TEST(Navigation, OpenFloorIsAStraightLine) {
  core::SceneCatalog scene;
  auto path = PlanRoute(scene, {0, 0}, {3, 1});
  ASSERT_TRUE(path.ok()) << path.status();
  ASSERT_EQ(path->points.size(), 2u);
  EXPECT_NEAR(path->length_m, std::hypot(3, 1), 1e-9);
  EXPECT_EQ(path->blocked_m, 0);
}

TEST(Navigation, GoesAroundATableWithClearance) {
  core::SceneCatalog scene;
  scene.objects.push_back(Block("table000", 2, 0, 0.5, 0.8));
  NavConfig cfg;
  auto path = PlanRoute(scene, {0, 0}, {4, 0}, cfg);
  ASSERT_TRUE(path.ok()) << path.status();
  EXPECT_GT(path->points.size(), 2u);
  EXPECT_EQ(path->blocked_m, 0);
  EXPECT_GE(path->min_clearance_m, cfg.body_radius_m);
  // around the 1.6 m wide table: longer than the straight 4 m, but not a wild detour
  EXPECT_GT(path->length_m, 4.2);
  EXPECT_LT(path->length_m, 6.0);
  // the table's footprint (inflated by the body radius) is never crossed
  for (size_t k = 0; k + 1 < path->points.size(); ++k) {
    for (double u = 0; u <= 1.0; u += 0.01) {
      Eigen::Vector2d p = path->points[k] + u * (path->points[k + 1] - path->points[k]);
      bool inside = std::abs(p.x() - 2) < 0.5 + 0.25 && std::abs(p.y()) < 0.8 + 0.25;
      EXPECT_FALSE(inside) << p.transpose();
    }
  }
}

TEST(Navigation, LowAndHighSolidsDoNotBlock) {
  core::SceneCatalog scene;
  scene.objects.push_back(Block("rug", 2, 0, 1.0, 1.0, 0.01));
  core::CatalogObject lamp = Block("lamp", 2, 0, 1.0, 1.0, 0.1);
  lamp.shapes[0].pose.pos.z() = 2.2;  // hangs above head height
  scene.objects.push_back(lamp);
  core::CatalogObject marker = Block("marker", 2, 0, 1.0, 1.0);
  marker.collides = false;
  scene.objects.push_back(marker);
  auto path = PlanRoute(scene, {0, 0}, {4, 0});
  ASSERT_TRUE(path.ok()) << path.status();
  EXPECT_EQ(path->points.size(), 2u);
  EXPECT_NEAR(path->length_m, 4.0, 1e-9);
}

TEST(Navigation, FindsTheGapInAWall) {
  core::SceneCatalog scene;
  // a wall along x = 2 from y = -5 to 5 with a 1.2 m gap centred at y = 2
  scene.objects.push_back(Block("wall_a", 2, -1.8, 0.05, 3.2));
  scene.objects.push_back(Block("wall_b", 2, 4.8, 0.05, 1.6));
  auto path = PlanRoute(scene, {0, 0}, {4, 0});
  ASSERT_TRUE(path.ok()) << path.status();
  EXPECT_EQ(path->blocked_m, 0);
  bool through_gap = false;
  for (size_t k = 0; k + 1 < path->points.size(); ++k) {
    const Eigen::Vector2d a = path->points[k], b = path->points[k + 1];
    if ((a.x() - 2) * (b.x() - 2) <= 0 && std::abs(b.x() - a.x()) > 1e-9) {
      double y = a.y() + (b.y() - a.y()) * (2 - a.x()) / (b.x() - a.x());
      through_gap = std::abs(y - 2) < 0.3;
    }
  }
  EXPECT_TRUE(through_gap);
}

TEST(Navigation, StandPointNextToFurnitureIsStillReached) {
  core::SceneCatalog scene;
  scene.objects.push_back(Block("chair000", 3, 0, 0.25, 0.25));
  // the stand point is 0.2 m in front of the chair, inside its body-radius band
  auto path = PlanRoute(scene, {0, 0}, {2.55, 0});
  ASSERT_TRUE(path.ok()) << path.status();
  EXPECT_NEAR((path->points.back() - Eigen::Vector2d(2.55, 0)).norm(), 0.0, 1e-12);
  EXPECT_NEAR(path->length_m, 2.55, 0.05);
}

TEST(Navigation, AGoalInAGapIsReachedAroundTheTableNotThroughIt) {
  // Table 7's desk: a chair block at x in [-0.25, 0.25], a table at [0.6, 1.4], y in [-0.6, 0.6];
  // the goal is in the 0.35 m gap between them, the start behind the table
  core::SceneCatalog scene;
  scene.objects.push_back(Block("chair000", 0, 0, 0.25, 0.25, 0.45));
  scene.objects.push_back(Block("table001", 1.0, 0, 0.4, 0.6, 0.38));
  auto path = PlanRoute(scene, {2.0, 0}, {0.42, 0});
  ASSERT_TRUE(path.ok()) << path.status();
  for (size_t k = 1; k < path->points.size(); ++k) {
    // no leg of the route crosses the table's footprint
    for (double u = 0; u <= 1.0; u += 0.02) {
      Eigen::Vector2d p = path->points[k - 1] + u * (path->points[k] - path->points[k - 1]);
      EXPECT_FALSE(p.x() > 0.62 && p.x() < 1.38 && std::abs(p.y()) < 0.58)
          << "through the table at " << p.transpose();
    }
  }
}

TEST(Navigation, StandingSpotMovesOutOfFurnitureWithinTheRadius) {
  core::SceneCatalog scene;
  scene.objects.push_back(Block("chair000", 0, 0, 0.25, 0.25, 0.45));
  scene.objects.push_back(Block("table001", 1.0, 0, 0.4, 0.6, 0.38));
  // a stand point 0.45 m in front of the chair lies 0.05 m inside the table
  const Eigen::Vector2d stand(0.7, 0);
  EXPECT_LT(PointClearance(scene, stand), 1e-9);
  Eigen::Vector2d spot = ClearStandingSpot(scene, stand, stand, 0.25, 0.2);
  EXPECT_LE((spot - stand).norm(), 0.25 + 1e-9);
  // the most room the gap offers: its middle, 0.175 m from both
  EXPECT_NEAR(spot.x(), 0.425, kSpotSearchStepM);
  EXPECT_GT(PointClearance(scene, spot), 0.15);
  // a point with room stays
  const Eigen::Vector2d open(-1.0, 0);
  EXPECT_EQ(ClearStandingSpot(scene, open, open, 0.25, 0.2), open);
}

TEST(Navigation, BadInputIsAnError) {
  core::SceneCatalog scene;
  NavConfig cfg;
  cfg.comfort_m = 0.1;  // below the body radius
  auto bad = PlanRoute(scene, {0, 0}, {1, 0}, cfg);
  ASSERT_FALSE(bad.ok());
  EXPECT_NE(bad.status().message().find("body_radius_m"), std::string::npos);
  auto nan = PlanRoute(scene, {0, 0}, {std::nan(""), 0});
  EXPECT_EQ(nan.status().code(), absl::StatusCode::kInvalidArgument);
  auto huge = PlanRoute(scene, {0, 0}, {500, 0});
  ASSERT_FALSE(huge.ok());
  EXPECT_NE(huge.status().message().find("max_extent_m"), std::string::npos);
}

TEST(Navigation, FollowerLeadsByTheLookaheadAndEndsAtTheGoal) {
  NavPath path;
  path.points = {{0, 0}, {2, 0}, {2, 2}};
  RouteFollower f(path, 1.0);
  auto c = f.Update({0, 0.1});
  EXPECT_FALSE(c.final);
  EXPECT_NEAR((c.point - Eigen::Vector2d(1, 0)).norm(), 0, 1e-9);
  EXPECT_NEAR(c.heading_rad, 0, 1e-9);
  EXPECT_NEAR(c.off_route_m, 0.1, 1e-9);
  c = f.Update({1.8, 0});
  EXPECT_NEAR((c.point - Eigen::Vector2d(2, 0.8)).norm(), 0, 1e-9);
  EXPECT_NEAR(c.heading_rad, M_PI / 2, 1e-9);
  // progress does not go back when the walker does
  c = f.Update({0, 0});
  EXPECT_NEAR((c.point - Eigen::Vector2d(2, 0.8)).norm(), 0, 1e-9);
  c = f.Update({2, 1.5});
  EXPECT_TRUE(c.final);
  EXPECT_NEAR((c.point - Eigen::Vector2d(2, 2)).norm(), 0, 1e-9);
}

TEST(Navigation, NearTheEndTheFollowerAimsAtTheLastCornerNotThroughIt) {
  // round a chair's back: the goal is 1 m from the walker, but behind a corner
  NavPath path;
  path.points = {{0, 0}, {0, 1}, {1, 1}, {1, 0.2}};
  RouteFollower f(path, 1.2);
  auto c = f.Update({0.05, 0.5});  // 2.3 m of route left: the carrot leads on the route
  EXPECT_FALSE(c.final);
  c = f.Update({0.8, 1.0});  // 1.0 m left, a corner at (1, 1) ahead
  EXPECT_FALSE(c.final);
  EXPECT_NEAR((c.point - Eigen::Vector2d(1, 1)).norm(), 0, 1e-9);
  c = f.Update({0.95, 0.95});  // past the corner: straight to the goal
  EXPECT_TRUE(c.final);
  EXPECT_NEAR((c.point - Eigen::Vector2d(1, 0.2)).norm(), 0, 1e-9);
}

// pure pursuit cuts corners: where the straight way to the carrot passes a block inside the
// turn closer than the route does, the carrot comes back along the route to a point the walker
// can head for in a straight line; in the open it stays
TEST(Navigation, TheCarrotComesBackWhenTheWayToItCutsACornerThroughABlock) {
  NavPath path;
  path.points = {{0, 0}, {2, 0}, {2, 2}};
  core::SceneCatalog scene;
  scene.objects.push_back(Block("stool000", 1.5, 0.6, 0.2, 0.2));
  NavConfig cfg;
  RouteFollower f(path, 1.2);
  const Eigen::Vector2d here(1.2, 0);
  const auto c = f.Update(here);
  EXPECT_NEAR((c.point - Eigen::Vector2d(2, 0.4)).norm(), 0, 1e-9);
  EXPECT_LT(WayClearance(scene, cfg, here, c.point), 0.25);
  const Eigen::Vector2d p = ClearCarrot(scene, cfg, f, here, c.point, 1.2);
  EXPECT_NEAR((p - f.PointAhead(0.9)).norm(), 0, 1e-9);
  EXPECT_GE(WayClearance(scene, cfg, here, p), kCarrotClearM - kCarrotSlackM);
  // nothing in the way: the carrot stays
  EXPECT_EQ(ClearCarrot(core::SceneCatalog(), cfg, f, here, c.point, 1.2), c.point);
}

// on a straight route the carrot keeps its lead; before a right-angle corner it comes to
// kTurnSlowMinM ahead on the way to it (the walker slows for the turn); a gentle bend in between
TEST(Navigation, TheCarrotComesNearerBeforeATurn) {
  NavPath straight;
  straight.points = {{0, 0}, {6, 0}};
  RouteFollower s(straight, 1.2);
  const Eigen::Vector2d here(1, 0);
  const auto cs = s.Update(here);
  EXPECT_EQ(SlowForTurn(s, here, cs.point, 1.2), cs.point);
  NavPath corner;
  corner.points = {{0, 0}, {2.5, 0}, {2.5, 3}};
  RouteFollower c(corner, 1.2);
  const Eigen::Vector2d at(1.3, 0);
  const auto cc = c.Update(at);
  ASSERT_NEAR((cc.point - Eigen::Vector2d(2.5, 0)).norm(), 0, 1e-9);
  const Eigen::Vector2d slow = SlowForTurn(c, at, cc.point, 1.2);
  EXPECT_NEAR((slow - at).norm(), kTurnSlowMinM, 1e-9);
  EXPECT_NEAR(slow.y(), 0, 1e-9);  // on the way to the carrot
  NavPath bend;
  bend.points = {{0, 0}, {2.5, 0}, {4.5, 0.6}};  // about 17 degrees: below kTurnSlowFromRad
  RouteFollower b(bend, 1.2);
  const auto cb = b.Update(at);
  EXPECT_EQ(SlowForTurn(b, at, cb.point, 1.2), cb.point);
  NavPath wide;
  wide.points = {{0, 0}, {2.5, 0}, {3.5, 1.5}};  // about 56 degrees: part of the lead
  RouteFollower w(wide, 1.2);
  const auto cw = w.Update(at);
  const double lead = (SlowForTurn(w, at, cw.point, 1.2) - at).norm();
  EXPECT_GT(lead, kTurnSlowMinM + 0.05);
  EXPECT_LT(lead, 1.2 - 0.05);
}

}  // namespace
}  // namespace simhuman::control
