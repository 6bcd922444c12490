#include "simhuman/control/manip/joint_path.h"

#include <gtest/gtest.h>

#include <cmath>

namespace simhuman::control::manip {
namespace {

constexpr double kTol = 1e-12;

Eigen::VectorXd V(std::initializer_list<double> v) {
  Eigen::VectorXd out(static_cast<int>(v.size()));
  int i = 0;
  for (double x : v) out[i++] = x;
  return out;
}

// free everywhere except an axis-aligned box (lo, hi) in the first two joints
ValidityFn BoxObstacle(double lo0, double hi0, double lo1, double hi1) {
  return [=](const Eigen::VectorXd& q) {
    return !(q[0] > lo0 && q[0] < hi0 && q[1] > lo1 && q[1] < hi1);
  };
}

TEST(JointPath, LengthsAndPointAt) {
  JointPath p;
  p.waypoints = {V({0, 0}), V({3, 4}), V({3, 4}), V({3, 6})};
  EXPECT_NEAR(p.Length(), 7.0, kTol);
  const std::vector<double> cum = CumulativeLengths(p);
  ASSERT_EQ(cum.size(), 4u);
  EXPECT_NEAR(cum[3], 7.0, kTol);
  EXPECT_TRUE(PointAt(p, 2.5).isApprox(V({1.5, 2})));
  EXPECT_TRUE(PointAt(p, 6.0).isApprox(V({3, 5})));
  EXPECT_TRUE(PointAt(p, -1.0).isApprox(V({0, 0})));
  EXPECT_TRUE(PointAt(p, 99.0).isApprox(V({3, 6})));
  EXPECT_EQ(SegmentAt(cum, 0.0), 0);
  EXPECT_EQ(SegmentAt(cum, 5.5), 2);  // skips the zero-length segment 1
}

TEST(JointPath, SegmentValidSeesAThinWallAtItsResolution) {
  // a wall 0.05 rad thick across joint 0; checks every 0.02 rad find it
  auto wall = [](const Eigen::VectorXd& q) { return !(q[0] > 0.50 && q[0] < 0.55); };
  EXPECT_FALSE(SegmentValid(V({0, 0}), V({1, 0.3}), wall, 0.02));
  EXPECT_TRUE(SegmentValid(V({0, 0}), V({0.45, 0.3}), wall, 0.02));
  int calls = 0;
  auto counting = [&](const Eigen::VectorXd&) {
    ++calls;
    return true;
  };
  EXPECT_TRUE(SegmentValid(V({0, 0}), V({1, -0.5}), counting, 0.1));
  EXPECT_EQ(calls, 10);  // b and 9 interior states, each once
}

TEST(JointPath, ShortcutStraightensAZigzagInFreeSpace) {
  JointPath p;
  for (int i = 0; i <= 10; ++i) p.waypoints.push_back(V({0.1 * i, (i % 2) ? 0.3 : -0.3}));
  p.waypoints.back() = V({1.0, 0.0});
  p.waypoints.front() = V({0.0, 0.0});
  auto free = [](const Eigen::VectorXd&) { return true; };
  core::Rng rng(7);
  auto out = ShortcutPath(p, free, {}, rng);
  ASSERT_TRUE(out.ok()) << out.status();
  ASSERT_EQ(out->size(), 2);
  EXPECT_TRUE(out->waypoints.front() == p.waypoints.front());
  EXPECT_TRUE(out->waypoints.back() == p.waypoints.back());
  EXPECT_NEAR(out->Length(), 1.0, kTol);
}

TEST(JointPath, ShortcutAroundAnObstacleStaysValidAndIsDeterministic) {
  // shortcuts see the box inflated by the check resolution, so the true box is never touched
  // between checked states (see SegmentValid)
  constexpr double kResolution = 0.01;
  const ValidityFn valid =
      BoxObstacle(-0.5 - kResolution, 0.5 + kResolution, -0.5 - kResolution, 0.5 + kResolution);
  const ValidityFn truth = BoxObstacle(-0.5, 0.5, -0.5, 0.5);
  // a detour far around the box
  JointPath p;
  p.waypoints = {V({-1, 0, 0}),  V({-1, 1.5, 0.2}), V({-0.3, 1.6, -0.2}), V({0.2, 1.4, 0.3}),
                 V({1, 1.5, 0}), V({1, 0.2, 0.1}),  V({1, 0, 0})};
  ASSERT_TRUE(PathValid(p, valid, kResolution));
  ShortcutOptions opt;
  opt.resolution_rad = kResolution;
  core::Rng rng_a(3), rng_b(3);
  auto a = ShortcutPath(p, valid, opt, rng_a);
  auto b = ShortcutPath(p, valid, opt, rng_b);
  ASSERT_TRUE(a.ok() && b.ok());
  EXPECT_TRUE(PathValid(*a, truth, 0.0005));
  EXPECT_LT(a->Length(), p.Length() * 0.8);
  // no shorter than going over the box's corners
  EXPECT_GT(a->Length(), 2 * std::hypot(1.0, 0.5) - 1e-6);
  ASSERT_EQ(a->size(), b->size());
  for (int i = 0; i < a->size(); ++i) EXPECT_TRUE(a->waypoints[i] == b->waypoints[i]);
}

TEST(JointPath, MalformedPathsAreRejected) {
  auto free = [](const Eigen::VectorXd&) { return true; };
  core::Rng rng(1);
  JointPath malformed_sizes;
  malformed_sizes.waypoints = {V({0, 0}), V({1, 1, 1})};
  auto s = ShortcutPath(malformed_sizes, free, {}, rng);
  ASSERT_FALSE(s.ok());
  EXPECT_NE(s.status().message().find("waypoint 1 has 3 joints"), std::string::npos);
  JointPath malformed_nan;
  malformed_nan.waypoints = {V({0, 0}), V({1, std::nan("")})};
  s = ShortcutPath(malformed_nan, free, {}, rng);
  ASSERT_FALSE(s.ok());
  EXPECT_NE(s.status().message().find("waypoint 1 joint 1 is not finite"), std::string::npos);
  ShortcutOptions bad;
  bad.resolution_rad = 0;
  JointPath ok;
  ok.waypoints = {V({0}), V({1})};
  EXPECT_FALSE(ShortcutPath(ok, free, bad, rng).ok());
  EXPECT_FALSE(ShortcutPath(JointPath{}, free, {}, rng).ok());
}

}  // namespace
}  // namespace simhuman::control::manip
