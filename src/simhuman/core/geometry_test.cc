// Frustums (cones, an hourglass's halves) and meshes: nearest points, surfaces, bounds, volumes;
// angles from cosines.
#include "simhuman/core/geometry.h"

#include <gtest/gtest.h>

#include <cmath>

namespace simhuman::core {
namespace {

constexpr double kTol = 1e-9;

Shape Frustum(double r_bottom, double half_height, double r_top) {
  Shape s;
  s.kind = ShapeKind::kFrustum;
  s.size = Eigen::Vector3d(r_bottom, half_height, r_top);
  return s;
}

// a unit cube [0, 1]^3 as twelve triangles, outward faces
std::shared_ptr<const Mesh> UnitCube() {
  auto m = std::make_shared<Mesh>();
  for (int i = 0; i < 8; ++i) m->vertices.emplace_back(i & 1, (i >> 1) & 1, (i >> 2) & 1);
  m->faces = {{0, 2, 1}, {1, 2, 3}, {4, 5, 6}, {5, 7, 6}, {0, 1, 4}, {1, 5, 4},
              {2, 6, 3}, {3, 6, 7}, {0, 4, 2}, {2, 4, 6}, {1, 3, 5}, {3, 7, 5}};
  m->lo = Eigen::Vector3d::Zero();
  m->hi = Eigen::Vector3d::Ones();
  return m;
}

TEST(AngleFromCosTest, ACosineRoundedPastOneGivesTheEndAngleNotNan) {
  EXPECT_NEAR(AngleFromCos(0.5), M_PI / 3, kTol);
  EXPECT_EQ(AngleFromCos(1.0 + 1e-12), 0.0);
  EXPECT_NEAR(AngleFromCos(-1.0 - 1e-12), M_PI, kTol);
  const Eigen::Vector3d a = Eigen::Vector3d(1, 2, 3).normalized();
  EXPECT_FALSE(std::isnan(AngleFromCos(a.dot(a))));
}

TEST(FrustumTest, NearestPointsOnAConeFromEverySide) {
  const Shape cone = Frustum(0.1, 0.2, 0.0);  // base at z = -0.2, apex at z = 0.2
  // inside: the point itself
  EXPECT_TRUE(
      NearestPointOnShape(cone, Pose(), {0.02, 0, 0}).isApprox(Eigen::Vector3d(0.02, 0, 0), kTol));
  // below the base: straight up onto it
  EXPECT_TRUE(NearestPointOnShape(cone, Pose(), {0.03, 0.04, -0.5})
                  .isApprox(Eigen::Vector3d(0.03, 0.04, -0.2), kTol));
  // above the apex: the apex
  EXPECT_TRUE(
      NearestPointOnShape(cone, Pose(), {0, 0, 0.7}).isApprox(Eigen::Vector3d(0, 0, 0.2), kTol));
  // beside the slanted side at mid height (radius 0.05 there): along the side's normal
  const Eigen::Vector3d np = NearestPointOnShape(cone, Pose(), {0.3, 0, 0});
  const Eigen::Vector2d side_dir = Eigen::Vector2d(-0.1, 0.4).normalized();  // base rim to apex
  const Eigen::Vector2d rel(np.x() - 0.1, np.z() + 0.2);
  EXPECT_NEAR(rel.x() * side_dir.y() - rel.y() * side_dir.x(), 0.0, kTol);  // on the side line
  EXPECT_NEAR((Eigen::Vector2d(0.3, 0) - Eigen::Vector2d(np.x(), np.z())).dot(side_dir), 0.0,
              kTol);  // the offset is normal to the side
  EXPECT_NEAR(np.y(), 0.0, kTol);
  // placed: a yawed, raised cone answers in world coordinates
  Pose world = Pose::FromYaw({1, 2, 3}, 0.7);
  const Eigen::Vector3d w = NearestPointOnShape(cone, world, world.Apply({0.03, 0.04, -0.5}));
  EXPECT_TRUE(w.isApprox(world.Apply({0.03, 0.04, -0.2}), kTol));
}

TEST(FrustumTest, AnHourglassHalfNarrowsToItsWaist) {
  const Shape half = Frustum(0.05, 0.1, 0.02);  // wide at the bottom, the waist at the top
  // at the top a point 0.03 out lies outside (the waist is 0.02); at the bottom it is inside
  EXPECT_FALSE(NearestPointOnShape(half, Pose(), {0.03, 0, 0.1})
                   .isApprox(Eigen::Vector3d(0.03, 0, 0.1), kTol));
  EXPECT_TRUE(NearestPointOnShape(half, Pose(), {0.03, 0, -0.1})
                  .isApprox(Eigen::Vector3d(0.03, 0, -0.1), kTol));
  EXPECT_NEAR(ShapeVolume(half), M_PI * 0.2 / 3 * (0.0025 + 0.001 + 0.0004), kTol);
  const auto [lo, hi] = LocalShapeBounds(half);
  EXPECT_TRUE(lo.isApprox(Eigen::Vector3d(-0.05, -0.05, -0.1), kTol));
  EXPECT_TRUE(hi.isApprox(Eigen::Vector3d(0.05, 0.05, 0.1), kTol));
}

TEST(FrustumTest, SurfaceSamplesLieOnTheSurface) {
  for (const Shape& s : {Frustum(0.1, 0.2, 0.0), Frustum(0.05, 0.1, 0.02)}) {
    const std::vector<Eigen::Vector3d> pts = SampleShapeSurface(s, 0.01);
    ASSERT_GT(pts.size(), 100u);
    for (const Eigen::Vector3d& p : pts) {
      // on the solid, and a point 1 mm further out from the axis or the nearer face is outside
      EXPECT_TRUE(NearestPointOnShape(s, Pose(), p).isApprox(p, 1e-9));
      const Eigen::Vector3d out =
          std::abs(std::abs(p.z()) - s.size.y()) < 1e-9
              ? Eigen::Vector3d(p + Eigen::Vector3d(0, 0, p.z() > 0 ? 1e-3 : -1e-3))
              : Eigen::Vector3d(p + 1e-3 * Eigen::Vector3d(p.x(), p.y(), 0).normalized());
      EXPECT_GT((NearestPointOnShape(s, Pose(), out) - out).norm(), 1e-4) << p.transpose();
    }
  }
}

TEST(MeshShapeTest, BoundsVolumeAndSamplesFollowTheScale) {
  Shape s;
  s.kind = ShapeKind::kMesh;
  s.mesh = UnitCube();
  s.size = Eigen::Vector3d(0.1, 0.2, 0.3);
  EXPECT_NEAR(ShapeVolume(s), 0.006, kTol);
  const auto [lo, hi] = LocalShapeBounds(s);
  EXPECT_TRUE(lo.isApprox(Eigen::Vector3d::Zero(), kTol));
  EXPECT_TRUE(hi.isApprox(Eigen::Vector3d(0.1, 0.2, 0.3), kTol));
  // the nearest point of a mesh is its bounding box's
  EXPECT_TRUE(NearestPointOnShape(s, Pose(), {0.5, 0.1, 0.1})
                  .isApprox(Eigen::Vector3d(0.1, 0.1, 0.1), kTol));
  for (const Eigen::Vector3d& p : SampleShapeSurface(s, 0.05)) {
    const Eigen::Vector3d q = p.cwiseQuotient(s.size);
    const bool on_face = (q.array().abs() < 1e-9).any() || ((q.array() - 1).abs() < 1e-9).any();
    EXPECT_TRUE(on_face) << p.transpose();
  }
  s.pose.pos = Eigen::Vector3d(1, 0, 0);
  const auto [wlo, whi] = ShapesBounds({s});
  EXPECT_TRUE(wlo.isApprox(Eigen::Vector3d(1, 0, 0), kTol));
  EXPECT_TRUE(whi.isApprox(Eigen::Vector3d(1.1, 0.2, 0.3), kTol));
}

}  // namespace
}  // namespace simhuman::core
