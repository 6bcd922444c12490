#include "simhuman/control/policy/route_steer.h"

#include <gtest/gtest.h>

#include <cmath>

namespace simhuman::control {
namespace {

RouteFollower::Carrot CarrotAt(double x, double y, bool final = false) {
  RouteFollower::Carrot c;
  c.point = Eigen::Vector2d(x, y);
  c.final = final;
  return c;
}

TEST(RouteSteer, WalksAtACarrotAheadAndFacesIt) {
  RouteSteer steer;
  WalkState s;
  steer.Steer({0, 0}, 0.3, CarrotAt(1.0, 0.5), {5, 5}, 2.0, &s);
  EXPECT_FALSE(steer.turning);
  EXPECT_EQ(s.target_xy, Eigen::Vector2d(1.0, 0.5));
  EXPECT_NEAR(s.target_yaw_rad, std::atan2(0.5, 1.0), 1e-12);
}

TEST(RouteSteer, TurnsOnTheSpotToACarrotBehindThenWalksAtIt) {
  RouteSteer steer;
  WalkState s;
  // the carrot behind: turn where it stands, facing the carrot
  steer.Steer({0, 0}, 0.0, CarrotAt(-1.2, 0), {5, 5}, 0.0, &s);
  EXPECT_TRUE(steer.turning);
  EXPECT_EQ(s.target_xy, Eigen::Vector2d(0, 0));
  EXPECT_NEAR(std::abs(s.target_yaw_rad), M_PI, 1e-12);
  // half-way round it keeps turning (0.6 rad is above kTurnDoneRad, below kTurnFirstRad)
  steer.Steer({0.05, 0}, M_PI - 0.6, CarrotAt(-1.2, 0), {5, 5}, 0.0, &s);
  EXPECT_TRUE(steer.turning);
  EXPECT_EQ(s.target_xy, Eigen::Vector2d(0.05, 0));
  // facing it: walk
  steer.Steer({0.05, 0}, M_PI - 0.2, CarrotAt(-1.2, 0), {5, 5}, 0.0, &s);
  EXPECT_FALSE(steer.turning);
  EXPECT_EQ(s.target_xy, Eigen::Vector2d(-1.2, 0));
}

TEST(RouteSteer, OnTheLastStretchFacesTheGoalThenTakesItsHeadingNearIt) {
  RouteSteer steer;
  WalkState s;
  const Eigen::Vector2d goal(2, 0);
  steer.Steer({1.0, 0}, 0.0, CarrotAt(2, 0, true), goal, 1.5, &s);
  EXPECT_EQ(s.target_xy, goal);
  EXPECT_NEAR(s.target_yaw_rad, 0.0, 1e-12);
  steer.Steer({2.0 - 0.9 * kFinalTurnM, 0}, 0.0, CarrotAt(2, 0, true), goal, 1.5, &s);
  EXPECT_TRUE(steer.final_turn);
  EXPECT_NEAR(s.target_yaw_rad, 1.5, 1e-12);
  // pushed a little away it keeps the heading; twice the distance away it faces the goal again
  steer.Steer({2.0 - 1.5 * kFinalTurnM, 0}, 0.0, CarrotAt(2, 0, true), goal, 1.5, &s);
  EXPECT_NEAR(s.target_yaw_rad, 1.5, 1e-12);
  steer.Steer({2.0 - 2.5 * kFinalTurnM, 0}, 0.0, CarrotAt(2, 0, true), goal, 1.5, &s);
  EXPECT_FALSE(steer.final_turn);
  EXPECT_NEAR(s.target_yaw_rad, 0.0, 1e-12);
}

}  // namespace
}  // namespace simhuman::control
