#include "simhuman/control/manip/retime.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

namespace simhuman::control::manip {
namespace {

constexpr double kTol = 1e-9;
// finite differences against analytic velocities (dt = 1/240 s)
constexpr double kFdTol = 1e-3;

Eigen::VectorXd V(std::initializer_list<double> v) {
  Eigen::VectorXd out(static_cast<int>(v.size()));
  int i = 0;
  for (double x : v) out[i++] = x;
  return out;
}

bool Has(const absl::Status& s, const std::string& text) {
  return s.message().find(text) != std::string::npos;
}

JointPath Bent() {
  JointPath p;
  p.waypoints = {V({0, 0, 0}), V({0.6, 0.4, -0.2}), V({1.2, 0.5, 0.3})};
  return p;
}

TEST(Retime, BellProfileEndsAtTheTerminalSpeed) {
  RetimeOptions opt;
  opt.duration_s = 1.5;
  opt.terminal_speed = 0.3;
  const JointPath path = Bent();
  auto traj = Retime(path, opt);
  ASSERT_TRUE(traj.ok()) << traj.status();
  EXPECT_DOUBLE_EQ(traj->duration_s(), 1.5);
  EXPECT_NEAR(traj->terminal_ratio(), 0.3 * 1.5 / path.Length(), kTol);
  ASSERT_EQ(traj->times().size(), traj->positions().size());
  EXPECT_EQ(traj->times().front(), 0.0);
  EXPECT_EQ(traj->times().back(), 1.5);
  EXPECT_TRUE(traj->positions().front().isApprox(path.waypoints.front(), kTol));
  EXPECT_TRUE(traj->positions().back().isApprox(path.waypoints.back(), kTol));
  EXPECT_LT(traj->velocities().front().norm(), kTol);
  EXPECT_NEAR(traj->velocities().back().norm(), 0.3, kTol);
  EXPECT_NEAR(traj->PathPosition(1.5), path.Length(), kTol);
  // accelerates, peaks inside, then decelerates to 0.3
  double peak = 0, peak_t = 0;
  for (double t : traj->times()) {
    if (traj->PathSpeed(t) > peak) {
      peak = traj->PathSpeed(t);
      peak_t = t;
    }
  }
  EXPECT_GT(peak_t, 0.5);
  EXPECT_LT(peak_t, 1.4);
  EXPECT_GT(peak, 0.3 * 1.5);
  EXPECT_LT(traj->accelerations().back().dot(traj->velocities().back()), 0);
  // velocities are the derivative of the positions (away from the bend)
  const auto& q = traj->positions();
  const double dt = opt.dt_s;
  for (size_t k = 1; k + 1 < q.size(); ++k) {
    const Eigen::VectorXd fd = (q[k + 1] - q[k - 1]) / (2 * dt);
    const Eigen::VectorXd v = traj->velocities()[k];
    if ((fd - v).norm() > kFdTol) {
      // only at the bend between the two segments
      EXPECT_NEAR(traj->PathPosition(traj->times()[k]), (path.waypoints[1]).norm(), 0.02);
    }
  }
  // Sample between samples agrees with the samples' neighbourhood
  const Trajectory::Point mid = traj->Sample(0.7 + 0.5 * dt);
  EXPECT_TRUE(mid.q.isApprox(0.5 * (traj->Sample(0.7).q + traj->Sample(0.7 + dt).q), 1e-4));
}

TEST(Retime, ZeroTerminalSpeedIsTheSymmetricReach) {
  RetimeOptions opt;
  opt.mean_speed = 0.5;
  const JointPath path = Bent();
  auto traj = Retime(path, opt);
  ASSERT_TRUE(traj.ok()) << traj.status();
  const double duration = path.Length() / 0.5;
  EXPECT_NEAR(traj->duration_s(), duration, kTol);
  EXPECT_NEAR(traj->PathSpeed(duration / 2), 1.5 * 0.5, kTol);  // peak 1.5 x mean at mid-time
  EXPECT_LT(traj->velocities().back().norm(), kTol);
}

TEST(Retime, VelocityLimitsStretchTheDuration) {
  RetimeOptions opt;
  opt.duration_s = 0.5;
  opt.terminal_speed = 0.2;
  opt.max_velocity = V({0.8, 1.0, 1.0});
  auto traj = Retime(Bent(), opt);
  ASSERT_TRUE(traj.ok()) << traj.status();
  EXPECT_GT(traj->duration_s(), 0.5);
  double worst = 0;
  for (double t = 0; t <= traj->duration_s(); t += 1e-4) {
    const Eigen::VectorXd v = traj->Sample(t).qdot;
    worst = std::max(worst, (v.cwiseAbs().array() / opt.max_velocity.array()).maxCoeff());
  }
  EXPECT_LE(worst, 1 + 1e-6);
  EXPECT_GT(worst, 0.99);  // stretched no more than needed
  EXPECT_NEAR(traj->velocities().back().norm(), 0.2, kTol);
}

TEST(Retime, SlowNominalDurationIsShortenedToKeepTheBell) {
  JointPath line;
  line.waypoints = {V({0, 0}), V({1, 0})};
  RetimeOptions opt;
  opt.duration_s = 10;
  opt.terminal_speed = 0.5;  // r would be 5
  auto traj = Retime(line, opt);
  ASSERT_TRUE(traj.ok()) << traj.status();
  EXPECT_NEAR(traj->duration_s(), 3.0, kTol);
  EXPECT_NEAR(traj->terminal_ratio(), 1.5, kTol);
}

TEST(Retime, ImpossibleRequestsNameTheCulprit) {
  RetimeOptions opt;
  opt.terminal_speed = 2.0;
  opt.max_velocity = V({2.0, 5.0, 0.5});
  auto r = Retime(Bent(), opt);
  ASSERT_FALSE(r.ok());
  EXPECT_TRUE(Has(r.status(), "moves joint 2 at")) << r.status();

  RetimeOptions malformed_limits;
  malformed_limits.max_velocity = V({1.0});
  r = Retime(Bent(), malformed_limits);
  ASSERT_FALSE(r.ok());
  EXPECT_TRUE(Has(r.status(), "max_velocity has 1 entries, the path has 3 joints"));

  RetimeOptions malformed_dt;
  malformed_dt.dt_s = 0;
  EXPECT_FALSE(Retime(Bent(), malformed_dt).ok());

  JointPath point;
  point.waypoints = {V({1, 2})};
  auto still = Retime(point, {});
  ASSERT_TRUE(still.ok()) << still.status();
  EXPECT_EQ(still->duration_s(), 0.0);
  EXPECT_EQ(still->positions().size(), 1u);
  RetimeOptions moving;
  moving.terminal_speed = 0.1;
  EXPECT_FALSE(Retime(point, moving).ok());
}

TEST(ReshapeTail, EndsAlongTheTangentAndKeepsThePrefix) {
  JointPath path;
  path.waypoints = {V({0, 0, 0}), V({1, 0, 0}), V({2, 0, 0})};
  const Eigen::VectorXd tangent = V({1, 1, 0});
  auto out = ReshapeTail(path, tangent, 0.1);
  ASSERT_TRUE(out.ok()) << out.status();
  EXPECT_TRUE(out->waypoints[0] == path.waypoints[0]);
  EXPECT_TRUE(out->waypoints[1] == path.waypoints[1]);
  EXPECT_TRUE(out->waypoints[2].isApprox(V({1.8, 0, 0}), kTol));  // the tail starts at 90 %
  EXPECT_TRUE(out->waypoints.back() == path.waypoints.back());
  EXPECT_EQ(out->size(), 3 + 24);
  const Eigen::VectorXd first = (out->waypoints[3] - out->waypoints[2]).normalized();
  EXPECT_GT(first.dot(V({1, 0, 0})), 0.99);  // leaves along the path
  EXPECT_GT(EndDirection(*out).dot(tangent.normalized()), 0.9999);

  // retimed, the final velocity points along the tangent with the terminal speed
  RetimeOptions opt;
  opt.duration_s = 2.0;
  opt.terminal_speed = 0.4;
  auto traj = Retime(*out, opt);
  ASSERT_TRUE(traj.ok()) << traj.status();
  const Eigen::VectorXd v_end = traj->velocities().back();
  EXPECT_NEAR(v_end.norm(), 0.4, kTol);
  EXPECT_GT(v_end.normalized().dot(tangent.normalized()), 0.9999);
}

TEST(ReshapeTail, MalformedInputsAreRejected) {
  const JointPath path = Bent();
  EXPECT_FALSE(ReshapeTail(path, V({1, 0, 0}), 0.0).ok());
  EXPECT_FALSE(ReshapeTail(path, V({1, 0, 0}), 1.5).ok());
  EXPECT_FALSE(ReshapeTail(path, V({0, 0, 0})).ok());
  auto r = ReshapeTail(path, V({1, 0}));
  ASSERT_FALSE(r.ok());
  EXPECT_TRUE(Has(r.status(), "of 3 joints (got 2 entries)")) << r.status();
  JointPath still;
  still.waypoints = {V({0, 0, 0}), V({0, 0, 0})};
  EXPECT_FALSE(ReshapeTail(still, V({1, 0, 0})).ok());
}

TEST(PalmSpeed, ApproachTangentAndTerminalPathSpeed) {
  Eigen::MatrixXd jac(3, 4);
  jac << 0.3, 0.1, 0.0, 0.2,  //
      0.0, 0.4, 0.1, 0.0,     //
      0.1, 0.0, 0.3, 0.1;
  const Eigen::Vector3d palm_dir(0.2, -1.0, 0.3);
  const Eigen::VectorXd dq = ApproachTangent(jac, palm_dir, 1e-4);
  EXPECT_NEAR(dq.norm(), 1.0, kTol);
  EXPECT_GT((jac * dq).normalized().dot(palm_dir.normalized()), 0.9999);
  auto speed = PathSpeedForPalmSpeed(jac, dq, 0.4);
  ASSERT_TRUE(speed.ok()) << speed.status();
  EXPECT_NEAR((jac * dq).norm() * *speed, 0.4, kTol);
  EXPECT_FALSE(PathSpeedForPalmSpeed(jac, V({1, 0}), 0.4).ok());
  EXPECT_FALSE(PathSpeedForPalmSpeed(Eigen::MatrixXd::Zero(3, 4), dq, 0.4).ok());
}

}  // namespace
}  // namespace simhuman::control::manip
