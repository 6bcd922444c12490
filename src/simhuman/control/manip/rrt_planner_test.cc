#include "simhuman/control/manip/rrt_planner.h"

#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <string>

namespace simhuman::control::manip {
namespace {

constexpr int kDofs = 7;
constexpr double kResolution = 0.02;
// the planner sees obstacles inflated by this much (>= resolution / 2, see SegmentValid), so
// its paths never touch the true obstacle between checked states
constexpr double kMargin = kResolution;
// checks of the result use a much finer resolution against the true obstacle
constexpr double kFineResolution = 0.001;

bool Has(const absl::Status& s, const std::string& text) {
  return s.message().find(text) != std::string::npos;
}

// A box obstacle in the joint box [-pi, pi]^7: |q0| < 0.5 and |qi| < 2 for i = 1..6. Paths from
// q0 = -2 to q0 = +2 must pass where some other joint is beyond 2 rad, a layer 1.14 rad thick.
struct BoxProblem {
  double margin = 0;
  bool operator()(const Eigen::VectorXd& q) const {
    if (std::abs(q[0]) >= 0.5 + margin) return true;
    for (int i = 1; i < kDofs; ++i) {
      if (std::abs(q[i]) >= 2.0 + margin) return true;
    }
    return false;
  }
};

Eigen::VectorXd Lower() { return Eigen::VectorXd::Constant(kDofs, -M_PI); }
Eigen::VectorXd Upper() { return Eigen::VectorXd::Constant(kDofs, M_PI); }

Eigen::VectorXd Start() {
  Eigen::VectorXd q = Eigen::VectorXd::Zero(kDofs);
  q[0] = -2.0;
  q[2] = 0.5;
  return q;
}

Eigen::VectorXd Goal() {
  Eigen::VectorXd q = Eigen::VectorXd::Zero(kDofs);
  q[0] = 2.0;
  q[3] = -0.5;
  return q;
}

TEST(RrtPlanner, SevenDofBoxIsSolvedQuicklyAndEverySegmentIsValid) {
  PlannerOptions opt;
  opt.time_limit_s = 0.2;
  opt.resolution_rad = kResolution;
  opt.seed = 11;
  const auto t0 = std::chrono::steady_clock::now();
  auto plan = PlanJointPath(Start(), {Goal()}, Lower(), Upper(), BoxProblem{kMargin}, opt);
  const double total_s =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  ASSERT_TRUE(plan.ok()) << plan.status();
  EXPECT_LT(total_s, 0.2);
  EXPECT_EQ(plan->goal_index, 0);
  EXPECT_FALSE(plan->start_escaped);
  const JointPath& path = plan->path;
  ASSERT_GE(path.size(), 3);  // must bend around the wall
  EXPECT_TRUE(path.waypoints.front() == Start());
  EXPECT_TRUE(path.waypoints.back() == Goal());
  const ValidityFn truth = BoxProblem{0.0};
  for (const Eigen::VectorXd& w : path.waypoints) {
    EXPECT_TRUE(truth(w));
    EXPECT_TRUE((w.array() >= Lower().array()).all() && (w.array() <= Upper().array()).all());
  }
  EXPECT_TRUE(PathValid(path, truth, kFineResolution));
  // shortcutting pays; reaching the inflated box's face from either end takes at least
  // |(1.48, 1.52)| (a lower bound)
  EXPECT_LT(path.Length(), 0.8 * plan->raw_length_rad);
  EXPECT_GT(path.Length(), 2 * std::hypot(1.48, 1.52));
  std::printf(
      "[ timing ] 7-DoF box: plan %.2f ms, shortcut %.2f ms, total %.2f ms; raw %d "
      "waypoints %.2f rad -> %d waypoints %.2f rad\n",
      1e3 * plan->planning_time_s, 1e3 * plan->simplify_time_s, 1e3 * total_s, plan->raw_waypoints,
      plan->raw_length_rad, path.size(), path.Length());
}

TEST(RrtPlanner, SameSeedSamePath) {
  PlannerOptions opt;
  opt.seed = 5;
  auto a = PlanJointPath(Start(), {Goal()}, Lower(), Upper(), BoxProblem{kMargin}, opt);
  auto b = PlanJointPath(Start(), {Goal()}, Lower(), Upper(), BoxProblem{kMargin}, opt);
  ASSERT_TRUE(a.ok() && b.ok());
  ASSERT_EQ(a->raw_waypoints, b->raw_waypoints);
  ASSERT_EQ(a->path.size(), b->path.size());
  for (int i = 0; i < a->path.size(); ++i) {
    EXPECT_TRUE(a->path.waypoints[i] == b->path.waypoints[i]) << "waypoint " << i;
  }
}

TEST(RrtPlanner, PicksTheReachableGoal) {
  // goal 0 sits inside a closed shell (valid itself, unreachable); goal 1 is free
  const Eigen::VectorXd enclosed = Eigen::VectorXd::Constant(kDofs, 1.5);
  const Eigen::VectorXd reachable = Eigen::VectorXd::Constant(kDofs, -1.0);
  auto valid = [&](const Eigen::VectorXd& q) {
    const double d = (q - enclosed).cwiseAbs().maxCoeff();
    return !(d > 0.3 && d < 0.6);
  };
  PlannerOptions opt;
  opt.time_limit_s = 0.5;
  Eigen::VectorXd start = Eigen::VectorXd::Zero(kDofs);
  auto plan = PlanJointPath(start, {enclosed, reachable}, Lower(), Upper(), valid, opt);
  ASSERT_TRUE(plan.ok()) << plan.status();
  EXPECT_EQ(plan->goal_index, 1);
  EXPECT_TRUE(plan->path.waypoints.back() == reachable);
  EXPECT_TRUE(PathValid(plan->path, valid, opt.resolution_rad));
}

TEST(RrtPlanner, UnreachableGoalIsNotFoundWithinTheTimeLimit) {
  const Eigen::VectorXd goal = Eigen::VectorXd::Constant(3, 1.0);
  auto valid = [&](const Eigen::VectorXd& q) {
    const double d = (q - goal).cwiseAbs().maxCoeff();
    return !(d > 0.2 && d < 0.4);
  };
  PlannerOptions opt;
  opt.time_limit_s = 0.05;
  auto plan = PlanJointPath(Eigen::VectorXd::Zero(3), {goal}, Eigen::VectorXd::Constant(3, -2),
                            Eigen::VectorXd::Constant(3, 2), valid, opt);
  ASSERT_FALSE(plan.ok());
  EXPECT_EQ(plan.status().code(), absl::StatusCode::kNotFound);
  EXPECT_TRUE(Has(plan.status(), "no collision-free path within 0.05 s")) << plan.status();
}

TEST(RrtPlanner, MarginallyInvalidStartCanEscape) {
  // the start lies 0.02 rad inside an obstacle below q1 = 0 (an object resting on a table)
  auto valid = [](const Eigen::VectorXd& q) { return q[1] >= 0.0; };
  Eigen::VectorXd start = Eigen::VectorXd::Zero(kDofs);
  start[1] = -0.02;
  Eigen::VectorXd goal = Eigen::VectorXd::Zero(kDofs);
  goal[0] = 1.0;
  goal[1] = 0.5;
  PlannerOptions opt;
  auto strict = PlanJointPath(start, {goal}, Lower(), Upper(), valid, opt);
  ASSERT_FALSE(strict.ok());
  EXPECT_EQ(strict.status().code(), absl::StatusCode::kInvalidArgument);
  EXPECT_TRUE(Has(strict.status(), "start_escape_rad")) << strict.status();

  opt.start_escape_rad = 0.05;
  auto plan = PlanJointPath(start, {goal}, Lower(), Upper(), valid, opt);
  ASSERT_TRUE(plan.ok()) << plan.status();
  EXPECT_TRUE(plan->start_escaped);
  // outside the escape ball, every state on the path is valid
  auto outside_valid = [&](const Eigen::VectorXd& q) {
    return (q - start).norm() <= opt.start_escape_rad || valid(q);
  };
  EXPECT_TRUE(PathValid(plan->path, outside_valid, 0.005));
}

TEST(RrtPlanner, BadInputsNameTheCulprit) {
  auto free = [](const Eigen::VectorXd&) { return true; };
  Eigen::VectorXd start = Eigen::VectorXd::Zero(kDofs);
  Eigen::VectorXd goal = Eigen::VectorXd::Constant(kDofs, 0.5);

  Eigen::VectorXd malformed_start = start;
  malformed_start[3] = std::nan("");
  auto r = PlanJointPath(malformed_start, {goal}, Lower(), Upper(), free);
  ASSERT_FALSE(r.ok());
  EXPECT_TRUE(Has(r.status(), "start joint 3 is NaN")) << r.status();

  Eigen::VectorXd malformed_goal = goal;
  malformed_goal[2] = 4.0;
  r = PlanJointPath(start, {goal, malformed_goal}, Lower(), Upper(), free);
  ASSERT_FALSE(r.ok());
  EXPECT_TRUE(Has(r.status(), "goal 1 joint 2 = 4 rad is outside its bounds [-3.14159, 3.14159]"))
      << r.status();

  r = PlanJointPath(Eigen::VectorXd::Zero(6), {goal}, Lower(), Upper(), free);
  ASSERT_FALSE(r.ok());
  EXPECT_TRUE(Has(r.status(), "start has 6 joints, the bounds have 7")) << r.status();

  Eigen::VectorXd malformed_upper = Upper();
  malformed_upper[4] = -4.0;
  r = PlanJointPath(start, {goal}, Lower(), malformed_upper, free);
  ASSERT_FALSE(r.ok());
  EXPECT_TRUE(Has(r.status(), "joint 4 bounds [-3.14159, -4]")) << r.status();

  r = PlanJointPath(start, std::vector<Eigen::VectorXd>{}, Lower(), Upper(), free);
  ASSERT_FALSE(r.ok());
  EXPECT_TRUE(Has(r.status(), "no goals"));

  auto blocked_goal = [&](const Eigen::VectorXd& q) { return !(q - goal).isZero(); };
  r = PlanJointPath(start, {goal}, Lower(), Upper(), blocked_goal);
  ASSERT_FALSE(r.ok());
  EXPECT_TRUE(Has(r.status(), "all 1 goal(s) are invalid")) << r.status();

  PlannerOptions malformed_options;
  malformed_options.time_limit_s = 0;
  r = PlanJointPath(start, {goal}, Lower(), Upper(), free, malformed_options);
  ASSERT_FALSE(r.ok());
  EXPECT_TRUE(Has(r.status(), "time_limit_s")) << r.status();
}

TEST(RrtPlanner, StartOnAGoalIsATrivialPath) {
  auto free = [](const Eigen::VectorXd&) { return true; };
  Eigen::VectorXd start = Eigen::VectorXd::Constant(kDofs, 0.1);
  const std::vector<Eigen::VectorXd> goals = {Eigen::VectorXd::Zero(kDofs), start};
  auto r = PlanJointPath(start, goals, Lower(), Upper(), free);
  ASSERT_TRUE(r.ok()) << r.status();
  EXPECT_EQ(r->goal_index, 1);
  EXPECT_EQ(r->path.Length(), 0.0);
}

TEST(RrtPlanner, AValidityCheckBudgetEndsTheSearchAlikeOnEveryRun) {
  // the goal sits inside a closed shell: no path exists, so the budget ends the search
  const Eigen::VectorXd goal = Eigen::VectorXd::Constant(3, 1.0);
  int64_t calls = 0;
  auto valid = [&](const Eigen::VectorXd& q) {
    ++calls;
    const double d = (q - goal).cwiseAbs().maxCoeff();
    return !(d > 0.2 && d < 0.4);
  };
  PlannerOptions opt;
  opt.time_limit_s = 60;  // the clock never binds: the result cannot depend on the machine
  opt.max_validity_checks = 2000;
  std::vector<int64_t> used;
  for (int run = 0; run < 2; ++run) {
    calls = 0;
    auto plan = PlanJointPath(Eigen::VectorXd::Zero(3), {goal}, Eigen::VectorXd::Constant(3, -2),
                              Eigen::VectorXd::Constant(3, 2), valid, opt);
    ASSERT_FALSE(plan.ok());
    EXPECT_EQ(plan.status().code(), absl::StatusCode::kNotFound);
    EXPECT_TRUE(Has(plan.status(), "within 2000 validity checks")) << plan.status();
    used.push_back(calls);
  }
  // the budget bounds the search (a check in flight may finish a segment), and binds alike
  EXPECT_GE(used[0], 2000);
  EXPECT_LT(used[0], 2000 + 1000);
  EXPECT_EQ(used[0], used[1]);
  // a reachable goal is still found within such a budget
  auto free_space = [](const Eigen::VectorXd&) { return true; };
  EXPECT_TRUE(PlanJointPath(Eigen::VectorXd::Zero(3), {goal}, Eigen::VectorXd::Constant(3, -2),
                            Eigen::VectorXd::Constant(3, 2), free_space, opt)
                  .ok());
  opt.max_validity_checks = -1;
  auto bad = PlanJointPath(Eigen::VectorXd::Zero(3), {goal}, Eigen::VectorXd::Constant(3, -2),
                           Eigen::VectorXd::Constant(3, 2), free_space, opt);
  ASSERT_FALSE(bad.ok());
  EXPECT_TRUE(Has(bad.status(), "max_validity_checks")) << bad.status();
}

}  // namespace
}  // namespace simhuman::control::manip
