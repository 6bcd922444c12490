#include "simhuman/control/manip/tracker.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <memory>
#include <string>

#include "simhuman/control/manip/retime.h"
#include "simhuman/core/check.h"
#include "simhuman/world/sim_world.h"

namespace simhuman::control::manip {
namespace {

constexpr double kTrackTol = 0.02;  // rad, the largest joint error along the trajectory
constexpr double kDt = 1.0 / 240.0;

// a 3-link arm: a vertical shoulder yaw, then two pitch joints, under gravity, with joint
// damping and armature (so the passive and implicit-damping terms matter), and unit-gear motors
constexpr char kArmXml[] = R"(
<mujoco model="arm3">
  <option timestep="0.004166666666666667" gravity="0 0 -9.81"/>
  <default>
    <joint type="hinge" damping="0.5" armature="0.01"/>
    <geom type="capsule" contype="0" conaffinity="0"/>
  </default>
  <worldbody>
    <body name="upper" pos="0 0 1">
      <joint name="yaw" axis="0 0 1"/>
      <joint name="pitch" axis="0 1 0"/>
      <geom fromto="0 0 0 0.3 0 0" size="0.04" mass="2"/>
      <body name="fore" pos="0.3 0 0">
        <joint name="elbow" axis="0 1 0"/>
        <geom fromto="0 0 0 0.3 0 0" size="0.035" mass="1.5"/>
        <body name="hand" pos="0.3 0 0">
          <joint name="wrist" axis="0 1 0"/>
          <geom fromto="0 0 0 0.1 0 0" size="0.03" mass="0.5"/>
        </body>
      </body>
    </body>
  </worldbody>
  <actuator>
    <motor joint="yaw"/> <motor joint="pitch"/> <motor joint="elbow"/> <motor joint="wrist"/>
  </actuator>
</mujoco>)";

struct Arm {
  mjModel* m = nullptr;
  mjData* d = nullptr;
  Arm() {
    auto model = world::SimWorld::CompileXml(kArmXml);
    SH_CHECK(model.ok(), "arm model");
    m = *model;
    d = mj_makeData(m);
  }
  ~Arm() {
    mj_deleteData(d);
    mj_deleteModel(m);
  }
  Eigen::VectorXd q() const { return Eigen::Map<const Eigen::VectorXd>(d->qpos, m->nq); }
  Eigen::VectorXd qdot() const { return Eigen::Map<const Eigen::VectorXd>(d->qvel, m->nv); }
};

Eigen::VectorXd V(std::initializer_list<double> v) {
  Eigen::VectorXd out(static_cast<int>(v.size()));
  int i = 0;
  for (double x : v) out[i++] = x;
  return out;
}

// a reach: a bent path with its last 10 % reshaped, retimed with a non-zero terminal speed
Trajectory Reach() {
  JointPath path;
  path.waypoints = {V({0, 0, 0, 0}), V({0.5, -0.4, 0.6, 0.1}), V({1.0, -0.6, 1.2, -0.3})};
  auto reshaped = ReshapeTail(path, V({0.2, -0.2, 1.0, 0.0}));
  SH_CHECK(reshaped.ok(), "reshape");
  RetimeOptions opt;
  opt.duration_s = 1.2;
  opt.terminal_speed = 0.4;
  opt.dt_s = kDt;
  auto traj = Retime(*reshaped, opt);
  SH_CHECK(traj.ok(), "retime");
  return *std::move(traj);
}

enum class Drive { kApplied, kMotors, kEq2 };

// largest joint error over the run and at its end (rad)
struct TrackStats {
  double worst = 0;
  double last = 0;
};

// tracks `traj` (then holds its end for `hold_s`) with an extra generalized force `disturbance`
TrackStats Track(const Trajectory& traj, Drive drive, const TrackerGains& gains, double hold_s = 0,
                 const Eigen::VectorXd& disturbance = Eigen::VectorXd()) {
  Arm arm;
  auto id = InverseDynamics::Create(arm.m, {0, 1, 2, 3});
  SH_CHECK(id.ok(), "inverse dynamics");
  JointTracker tracker(4, gains);
  Eigen::Map<Eigen::VectorXd>(arm.d->qpos, 4) = traj.Sample(0).q;
  TrackStats stats;
  const int steps = static_cast<int>((traj.duration_s() + hold_s) / kDt);
  for (int k = 0; k < steps; ++k) {
    const double t = k * kDt;
    mj_step1(arm.m, arm.d);
    Trajectory::Point ref = traj.Sample(t);
    if (t > traj.duration_s()) {  // hold the end
      ref.qdot.setZero();
      ref.qddot.setZero();
    }
    Eigen::VectorXd acc;
    if (drive == Drive::kEq2) {
      const Eigen::VectorXd next =
          NextVelocity(arm.q(), arm.qdot(), ref.q, ref.qdot, gains.kp, gains.kd, kDt);
      acc = (next - arm.qdot()) / kDt;
    } else {
      acc = tracker.DesiredAcceleration(arm.q(), arm.qdot(), ref.q, ref.qdot, ref.qddot, kDt);
    }
    const Eigen::VectorXd tau = id->Torque(arm.d, acc);
    if (drive == Drive::kMotors) {
      for (int i = 0; i < 4; ++i) arm.d->ctrl[i] = tau[i];
    } else {
      id->Apply(arm.d, tau);
    }
    if (disturbance.size() == 4) {
      for (int i = 0; i < 4; ++i) arm.d->qfrc_applied[i] += disturbance[i];
    }
    mj_step2(arm.m, arm.d);
    const Trajectory::Point now = traj.Sample(t + kDt);
    stats.last = (arm.q() - now.q).cwiseAbs().maxCoeff();
    stats.worst = std::max(stats.worst, stats.last);
  }
  return stats;
}

TEST(Tracker, NextVelocityIsEq2) {
  const Eigen::VectorXd q = V({0.1, -0.2}), qdot = V({0.5, 0.0});
  const Eigen::VectorXd q_ref = V({0.0, 0.0}), zero = V({0, 0});
  const double kp = 600, kd = 49, dt = 1.0 / 240;
  // Eq. 2 with per-step gains Kp = dt kp, Kd = dt kd and a resting reference
  const Eigen::VectorXd eq2 = -(dt * kp) * (q - q_ref) - (dt * kd - 1) * qdot;
  EXPECT_TRUE(NextVelocity(q, qdot, q_ref, zero, kp, kd, dt).isApprox(eq2, 1e-12));
  // on the reference, the next velocity is the reference's
  const Eigen::VectorXd v_ref = V({0.3, -0.1});
  EXPECT_TRUE(NextVelocity(q, v_ref, q, v_ref, kp, kd, dt).isApprox(v_ref, 1e-12));
}

TEST(Tracker, InverseDynamicsRealisesTheAcceleration) {
  Arm arm;
  Eigen::Map<Eigen::VectorXd>(arm.d->qpos, 4) = V({0.3, -0.5, 0.8, 0.2});
  Eigen::Map<Eigen::VectorXd>(arm.d->qvel, 4) = V({0.5, -0.2, 0.1, 1.0});
  auto id = InverseDynamics::Create(arm.m, {0, 1, 2, 3});
  ASSERT_TRUE(id.ok()) << id.status();
  const Eigen::VectorXd want = V({1.0, -2.0, 3.0, 0.5});
  mj_step1(arm.m, arm.d);
  id->Apply(arm.d, id->Torque(arm.d, want));
  const Eigen::VectorXd v0 = arm.qdot();
  mj_step2(arm.m, arm.d);
  // semi-implicit Euler: the velocity changed by dt * qacc exactly (damping included)
  EXPECT_TRUE(((arm.qdot() - v0) / kDt).isApprox(want, 1e-9)) << ((arm.qdot() - v0) / kDt);
}

TEST(Tracker, InverseDynamicsRejectsBadDofs) {
  Arm arm;
  auto r = InverseDynamics::Create(arm.m, {0, 4});
  ASSERT_FALSE(r.ok());
  EXPECT_NE(r.status().message().find("dof 4 (entry 1) is outside [0, 4)"), std::string::npos)
      << r.status();
  EXPECT_FALSE(InverseDynamics::Create(arm.m, {1, 1}).ok());
  EXPECT_FALSE(InverseDynamics::Create(arm.m, {}).ok());
}

TEST(Tracker, RetimedReachIsTrackedThroughAppliedForcesMotorsAndEq2) {
  const Trajectory traj = Reach();
  const double applied = Track(traj, Drive::kApplied, {}).worst;
  const double motors = Track(traj, Drive::kMotors, {}).worst;
  const double eq2 = Track(traj, Drive::kEq2, {}).worst;
  std::printf("[ tracking ] max joint error: qfrc_applied %.5f, motors %.5f, Eq. 2 %.5f rad\n",
              applied, motors, eq2);
  EXPECT_LT(applied, kTrackTol);
  EXPECT_LT(motors, kTrackTol);
  EXPECT_LT(eq2, kTrackTol);
}

TEST(Tracker, IntegralTermRemovesTheSagOfAnUnmodelledLoad) {
  // a constant torque the model does not know (a held object), the reference at rest
  JointPath still;
  still.waypoints = {V({0.2, -0.3, 0.6, 0.0})};
  auto traj = Retime(still, {});
  ASSERT_TRUE(traj.ok());
  const Eigen::VectorXd load = V({0.0, 12.0, 6.0, 1.5});  // N m
  TrackerGains pd;
  pd.ki = 0;
  // the PD alone settles at an offset of about M^-1 load / kp; the integral pulls it back
  const TrackStats with_pd = Track(*traj, Drive::kApplied, pd, 3.0, load);
  const TrackStats with_pid = Track(*traj, Drive::kApplied, {}, 3.0, load);
  std::printf("[ tracking ] unmodelled load after 3 s: PD %.4f rad, PID %.5f rad (worst %.4f)\n",
              with_pd.last, with_pid.last, with_pid.worst);
  EXPECT_GT(with_pd.last, 0.01);
  EXPECT_LT(with_pid.last, 0.1 * with_pd.last);
}

}  // namespace
}  // namespace simhuman::control::manip
