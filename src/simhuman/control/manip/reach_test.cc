#include "simhuman/control/manip/reach.h"

#include <gtest/gtest.h>

#include <cmath>
#include <memory>

#include "simhuman/control/manip/carry_over.h"
#include "simhuman/control/manip/grasp_task.h"
#include "simhuman/control/manip/tabletop_pipeline.h"
#include "simhuman/world/objects.h"
#include "simhuman/world/scene.h"
#include "simhuman/world/seating.h"
#include "simhuman/world/sim_world.h"
#include "simhuman/world/tabletop.h"

namespace simhuman::control::manip {
namespace {

// the tabletop layout's table, chair and seated human, and a cylinder in the region
std::unique_ptr<world::SimWorld> TableScene(const Eigen::Vector3d& can_table) {
  world::SceneSpec spec = world::TabletopBaseScene("reach");
  world::ObjectSpec can;
  can.id = "cylinder002";
  can.type = "cylinder";
  can.pos = world::TableToWorld(can_table);
  can.size = {{"radius", 0.04}, {"height", 0.15}};
  can.mass_kg = 2.0;
  spec.objects.push_back(can);
  auto catalog = world::BuildCatalog(spec);
  EXPECT_TRUE(catalog.ok()) << catalog.status();
  auto human = world::AgentFromHuman(spec.humans[0], 0, *catalog);
  EXPECT_TRUE(human.ok()) << human.status();
  world::ModelOptions opt;
  opt.timestep_s = 1.0 / 240;
  auto w = world::SimWorld::Create(*catalog, {*human}, opt);
  EXPECT_TRUE(w.ok()) << w.status();
  return std::move(*w);
}

// the right arm's and hand's index, the hand opened (SetOpenHand) and the kinematics run
GraspIndex OpenTheHand(world::SimWorld& w) {
  const GraspIndex gi = *MakeGraspIndex(w, 0, true);
  SetOpenHand(gi, w.data());
  mj_forward(w.model(), w.data());
  return gi;
}

// the arm settles where it hangs, the hand open, as the pipeline's pre-shape leaves it
void SettleTheHangingArm(world::SimWorld& w, const GraspIndex& gi) {
  mjData* d = w.data();
  for (int k = 0; k < kGraspDofs; ++k) d->ctrl[gi.actuator[k]] = d->qpos[gi.qpos[k]];
  for (int k = 0; k < 60; ++k) mj_step(w.model(), d);
}

std::vector<PalmPose> Around(const Eigen::Vector3d& centre, double standoff) {
  std::vector<PalmPose> out;
  for (int k = 0; k < 16; ++k)
    out.push_back(SideGraspPose(centre, standoff, -M_PI + k * M_PI / 8, true));
  return out;
}

TEST(ReachTest, TheArmReachesAPreGraspBesideAnObjectAndTracksItIntegration) {
  const Eigen::Vector3d can_table(0.05, 0.2, 0);
  auto w = TableScene(can_table);
  const mjModel* m = w->model();
  mjData* d = w->data();
  const GraspIndex gi = OpenTheHand(*w);
  const ArmChain& arm = gi.arm;
  for (int k = 0; k < kGraspDofs; ++k) d->ctrl[gi.actuator[k]] = d->qpos[gi.qpos[k]];
  mjData* s = mj_makeData(m);
  const Eigen::Vector3d centre = world::TableToWorld(can_table) + Eigen::Vector3d(0, 0, 0.055);
  const std::vector<PalmPose> goals = Around(centre, 0.04 + 0.04);
  ArmMotionOptions o;
  std::vector<Eigen::Vector3d> approach;
  for (const PalmPose& g : goals) approach.push_back(g.rot.col(1));  // out of the palm
  auto motion = PlanArmMotion(m, d, s, arm, goals, approach, o);
  ASSERT_TRUE(motion.ok()) << motion.status();
  EXPECT_GE(motion->goals_reachable, 1);
  EXPECT_GT(motion->trajectory.duration_s(), 0.3);
  EXPECT_LT(motion->trajectory.duration_s(), 3.0);
  EXPECT_LT(motion->plan_time_s, 2.0);
  // execute it
  auto tracker = ArmTracker::Create(m, arm);
  ASSERT_TRUE(tracker.ok()) << tracker.status();
  const PalmPose& goal = goals[motion->goal_index];
  double max_err = 0;
  const int steps = static_cast<int>((motion->trajectory.duration_s() + 0.3) / m->opt.timestep);
  for (int k = 0; k < steps; ++k) {
    mj_step1(m, d);
    tracker->Control(motion->trajectory, d->time, d);
    mj_step2(m, d);
    const Eigen::VectorXd ref =
        motion->trajectory.Sample(std::min(d->time, motion->trajectory.duration_s())).q;
    max_err = std::max(max_err, (arm.Get(d) - ref).cwiseAbs().maxCoeff());
  }
  const Eigen::Vector3d palm(d->site_xpos + 3 * arm.palm_site);
  EXPECT_LT((palm - goal.pos).norm(), 0.02);
  EXPECT_LT(max_err, 0.08) << "largest joint tracking error (rad)";
  // the object was not touched
  const int can = mj_name2id(m, mjOBJ_BODY, world::ObjectBodyName("cylinder002").c_str());
  EXPECT_LT((Eigen::Vector3d(d->xpos + 3 * can) - world::TableToWorld(can_table)).norm(), 0.005);
  mj_deleteData(s);
}

TEST(ReachTest, AnUnreachablePalmPoseIsAPlanFailure) {
  auto w = TableScene(Eigen::Vector3d(0.05, 0.2, 0));
  ArmChain arm = *MakeArmChain(*w, 0, true);
  mjData* s = mj_makeData(w->model());
  // 1.5 m away across the table
  auto motion =
      PlanArmMotion(w->model(), w->data(), s, arm, Around(Eigen::Vector3d(2.0, 0, 0.8), 0.08), {});
  ASSERT_FALSE(motion.ok());
  EXPECT_NE(
      motion.status().message().find("plan failure: no collision-free arm pose for any of 16"),
      std::string::npos)
      << motion.status();
  mj_deleteData(s);
}

TEST(ReachTest, ACarriedObjectMovesWithTheHandInTheCollisionCheck) {
  // the can floats under the table's board (as if held there); the palm's goal lies 20 cm above
  // the hanging hand, which the arm reaches freely, but which lifts the can through the board
  auto w = TableScene(Eigen::Vector3d(0.2, 0.2, -0.25));
  const mjModel* m = w->model();
  mjData* d = w->data();
  mj_forward(m, d);
  const ArmChain arm = *MakeArmChain(*w, 0, true);
  const int can = mj_name2id(m, mjOBJ_BODY, world::ObjectBodyName("cylinder002").c_str());
  mjData* s = mj_makeData(m);
  PalmPose up;
  up.pos = Eigen::Vector3d(d->site_xpos + 3 * arm.palm_site) + Eigen::Vector3d(0, 0, 0.2);
  up.rot =
      Eigen::Map<const Eigen::Matrix<double, 3, 3, Eigen::RowMajor>>(d->xmat + 9 * arm.hand_body);
  ArmMotionOptions o;
  o.ignore_bodies = {can};  // as the transport ignores the held object's contacts with the hand
  auto arm_only = PlanArmMotion(m, d, s, arm, {up}, {}, o);
  ASSERT_TRUE(arm_only.ok()) << arm_only.status();
  o.carried_body = can;
  auto carried = PlanArmMotion(m, d, s, arm, {up}, {}, o);
  ASSERT_FALSE(carried.ok());
  EXPECT_NE(carried.status().message().find("1 in collision"), std::string::npos)
      << carried.status();
  mj_deleteData(s);
}

TEST(ReachTest, TheHangingHandRisesOverTheTableEdgeThroughTheRaiseVias) {
  auto w = TableScene(Eigen::Vector3d(0.05, 0.2, 0));
  const mjModel* m = w->model();
  mjData* d = w->data();
  const GraspIndex gi = OpenTheHand(*w);
  const ArmChain& arm = gi.arm;
  SettleTheHangingArm(*w, gi);
  mjData* s = mj_makeData(m);
  const double table_top = world::TableToWorld(Eigen::Vector3d::Zero()).z();
  ASSERT_LT(d->site_xpos[3 * arm.palm_site + 2], table_top) << "the hand hangs below the board";
  std::vector<Eigen::VectorXd> vias;
  for (const std::vector<double>& v : SeatedRaiseViaRad())
    vias.push_back(Eigen::Map<const Eigen::VectorXd>(v.data(), static_cast<int>(v.size())));
  auto raise = PlanArmThrough(m, d, s, arm, vias, {});
  ASSERT_TRUE(raise.ok()) << raise.status();
  // the path passes every via (straight segments between) and ends at rest at the last
  const Trajectory& t = raise->trajectory;
  EXPECT_LT((t.Sample(t.duration_s()).q - arm.Clamp(vias.back())).norm(), 1e-6);
  EXPECT_LT(t.Sample(t.duration_s()).qdot.norm(), 1e-6);
  arm.Set(s, arm.Clamp(vias.back()));
  mj_kinematics(m, s);
  EXPECT_GT(s->site_xpos[3 * arm.palm_site + 2], table_top + 0.03)
      << "the palm ends over the board";
  // the palm never swings out: within 40 cm of the shoulder's vertical line all the way
  const Eigen::Vector3d shoulder(d->site_xpos + 3 * gi.shoulder_site);
  double widest = 0;
  for (double at = 0; at <= t.duration_s(); at += 0.02) {
    arm.Set(s, t.Sample(at).q);
    mj_kinematics(m, s);
    widest = std::max(
        widest, (Eigen::Vector3d(s->site_xpos + 3 * arm.palm_site) - shoulder).head<2>().norm());
  }
  EXPECT_LT(widest, 0.4);
  // a via inside the board, and a via of the wrong size, are refused by name
  Eigen::VectorXd into = arm.Clamp(vias.back());
  into[1] = 1.2;  // the shoulder flexed, the forearm pointing down through the board
  into[3] = 0.3;
  auto blocked = PlanArmThrough(m, d, s, arm, {vias[0], into}, {});
  ASSERT_FALSE(blocked.ok());
  EXPECT_NE(blocked.status().message().find("via 1 is in collision"), std::string::npos)
      << blocked.status();
  auto short_via = PlanArmThrough(m, d, s, arm, {Eigen::VectorXd::Zero(3)}, {});
  ASSERT_FALSE(short_via.ok());
  EXPECT_NE(short_via.status().message().find("via 0 has 3 arm angles, not 7"), std::string::npos)
      << short_via.status();
  mj_deleteData(s);
}

TEST(ReachTest, TheRaisedHandJoinsTheLastPartOfAReachFromTheHangingArmIntegration) {
  auto w = TableScene(Eigen::Vector3d(0.05, 0.2, 0));
  const mjModel* m = w->model();
  mjData* d = w->data();
  const GraspIndex gi = OpenTheHand(*w);
  const ArmChain& arm = gi.arm;
  SettleTheHangingArm(*w, gi);
  mjData* s = mj_makeData(m);
  // the reach planned from the hanging arm, and its part from 20 cm out
  const Eigen::Vector3d centre = world::TableToWorld(Eigen::Vector3d(0.05, 0.2, 0.055));
  const std::vector<PalmPose> goals = Around(centre, 0.08);
  std::vector<Eigen::Vector3d> approach;
  for (const PalmPose& g : goals) approach.push_back(g.rot.col(1));
  ArmMotionOptions o;  // the can is what the hand goes for, as in the pipeline
  o.approach_body = mj_name2id(m, mjOBJ_BODY, world::ObjectBodyName("cylinder002").c_str());
  auto reach = PlanArmMotion(m, d, s, arm, goals, approach, o);
  ASSERT_TRUE(reach.ok()) << reach.status();
  const JointPath& whole = reach->trajectory.path();
  const JointPath tail = PathTail(m, d, s, arm, whole, 0.2);
  auto palm_at = [&](const Eigen::VectorXd& q) {
    arm.Set(s, q);
    mj_kinematics(m, s);
    return Eigen::Vector3d(s->site_xpos + 3 * arm.palm_site);
  };
  const Eigen::Vector3d end = palm_at(whole.waypoints.back());
  ASSERT_GE(tail.size(), 2);
  EXPECT_NEAR((palm_at(tail.waypoints.front()) - end).norm(), 0.2, 0.01);
  EXPECT_LT(tail.Length(), whole.Length());
  EXPECT_EQ(tail.waypoints.back(), whole.waypoints.back());
  EXPECT_EQ(PathTail(m, d, s, arm, whole, 5.0).size(), whole.size()) << "nowhere 5 m out";
  // the hand raised over the board's edge, then onto that part and along it
  std::vector<Eigen::VectorXd> vias;
  for (const std::vector<double>& v : SeatedRaiseViaRad())
    vias.push_back(Eigen::Map<const Eigen::VectorXd>(v.data(), static_cast<int>(v.size())));
  arm.Set(d, arm.Clamp(vias.back()));
  mj_forward(m, d);
  auto onto = PlanArmOnto(m, d, s, arm, tail, o);
  ASSERT_TRUE(onto.ok()) << onto.status();
  const Trajectory& t = onto->trajectory;
  EXPECT_LT((t.Sample(0).q - arm.Clamp(vias.back())).norm(), 1e-6);
  const JointPath& joined = t.path();
  ASSERT_GE(joined.size(), tail.size());
  for (int i = 0; i < tail.size(); ++i) {
    EXPECT_EQ(joined.waypoints[joined.size() - tail.size() + i], tail.waypoints[i]) << i;
  }
  // arriving with DASH's terminal palm speed
  const Trajectory::Point last = t.Sample(t.duration_s());
  arm.Set(s, last.q);
  mj_kinematics(m, s);
  mj_comPos(m, s);
  std::vector<mjtNum> jacp(3 * m->nv);
  mj_jacSite(m, s, jacp.data(), nullptr, arm.palm_site);
  Eigen::Vector3d v = Eigen::Vector3d::Zero();
  for (int i = 0; i < ArmChain::kDofs; ++i) {
    for (int k = 0; k < 3; ++k) v[k] += jacp[k * m->nv + arm.dof[i]] * last.qdot[i];
  }
  EXPECT_NEAR(v.norm(), 0.4, 0.05);
  // an empty part, and a part through the board, are refused by name
  auto empty = PlanArmOnto(m, d, s, arm, JointPath{}, {});
  ASSERT_FALSE(empty.ok());
  EXPECT_NE(empty.status().message().find("empty tail"), std::string::npos) << empty.status();
  Eigen::VectorXd into = arm.Clamp(vias.back());
  into[1] = 1.2;
  into[3] = 0.3;
  JointPath blocked_tail;
  blocked_tail.waypoints = {into, tail.waypoints.back()};
  auto blocked = PlanArmOnto(m, d, s, arm, blocked_tail, o);
  ASSERT_FALSE(blocked.ok());
  EXPECT_NE(blocked.status().message().find("the tail is in collision"), std::string::npos)
      << blocked.status();
  mj_deleteData(s);
}

// Holding the arm reached out over the table while a load the inverse dynamics does not know
// about comes on at once (30 N, an object of 3 kg, 6 cm out of the palm, as the table stops
// bearing it): the largest sag of the forearm and wrist joints in the next 0.5 s.
double LoadedWristSag(double min_inertia) {
  auto w = TableScene(Eigen::Vector3d(0.3, -0.2, 0));  // the can out of the way
  const mjModel* m = w->model();
  mjData* d = w->data();
  const GraspIndex gi = OpenTheHand(*w);
  const ArmChain& arm = gi.arm;
  mjData* s = mj_makeData(m);
  mju_copy(s->qpos, d->qpos, m->nq);
  const PalmPose goal =
      SideGraspPose(world::TableToWorld(Eigen::Vector3d(0.05, 0.2, 0.09)), 0.0, M_PI / 2, true);
  const IkResult ik = SolvePalmIk(m, s, arm, goal, arm.Get(d), arm.Get(d));
  mj_deleteData(s);
  EXPECT_LT(ik.pos_err_m, 0.01);
  arm.Set(d, ik.q);
  mj_forward(m, d);
  for (int k = 0; k < kGraspDofs; ++k) d->ctrl[gi.actuator[k]] = d->qpos[gi.qpos[k]];
  TrackerGains gains;
  gains.min_inertia = min_inertia;
  auto tracker = ArmTracker::Create(m, arm, gains);
  EXPECT_TRUE(tracker.ok()) << tracker.status();
  double sag = 0;
  for (int k = 0; k < static_cast<int>(1.0 / m->opt.timestep); ++k) {
    mj_step1(m, d);
    tracker->Hold(ik.q, d);
    mj_step2(m, d);
  }
  // the load comes on at once (the table stops bearing the object as the lift begins)
  for (int k = 0; k < static_cast<int>(0.5 / m->opt.timestep); ++k) {
    mj_step1(m, d);
    // the load: 30 N down at a point 6 cm out of the palm
    const int hb = arm.hand_body;
    const Eigen::Map<const Eigen::Matrix<double, 3, 3, Eigen::RowMajor>> rh(d->xmat + 9 * hb);
    const Eigen::Vector3d at =
        Eigen::Vector3d(d->site_xpos + 3 * arm.palm_site) + 0.06 * rh.col(1) * (arm.right ? 1 : -1);
    const Eigen::Vector3d f(0, 0, -30);
    const Eigen::Vector3d tau = (at - Eigen::Vector3d(d->xipos + 3 * hb)).cross(f);
    for (int i = 0; i < 3; ++i) {
      d->xfrc_applied[6 * hb + i] = f[i];
      d->xfrc_applied[6 * hb + 3 + i] = tau[i];
    }
    tracker->Hold(ik.q, d);
    mj_step2(m, d);
    for (int j = 4; j < ArmChain::kDofs; ++j) {
      sag = std::max(sag, std::abs(d->qpos[arm.qpos[j]] - ik.q[j]));
    }
  }
  return sag;
}

TEST(ReachTest, AnInertiaFloorHoldsTheWristUnderALoadItDoesNotModelIntegration) {
  const double soft = LoadedWristSag(0.0), stiff = LoadedWristSag(0.03);
  std::printf("forearm and wrist sag under 30 N: %.3f rad without the floor, %.3f with it\n", soft,
              stiff);
  EXPECT_LT(stiff, 0.08);
  EXPECT_LT(stiff, 0.6 * soft);
}

TEST(CarryOverTest, TheArcLeavesAndArrivesVerticallyOverTheGivenLift) {
  PalmPose from, to;
  from.pos = Eigen::Vector3d(0, 0, 1.0);
  to.pos = Eigen::Vector3d(0.4, 0.1, 1.02);
  to.rot = Eigen::AngleAxisd(0.5, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  const Eigen::Vector3d held(0, 0.03, -0.05);  // the object's base below the palm
  const std::vector<PalmPose> arc = OverArcPalmPath(from, to, held, 0.12, 0.02);
  ASSERT_GE(arc.size(), 20u);
  EXPECT_LT((arc.back().pos - to.pos).norm(), 1e-9);
  EXPECT_LT((arc.back().rot - to.rot).norm(), 1e-9);
  Eigen::Vector3d prev = from.pos + from.rot * held;
  double top = -1e9;
  for (const PalmPose& p : arc) {
    const Eigen::Vector3d b = p.pos + p.rot * held;
    EXPECT_LE((b - prev).norm(), 0.02 + 1e-9);
    top = std::max(top, b.z());
    prev = b;
  }
  // the top 12 cm over the higher end; the first and last steps mostly vertical
  EXPECT_NEAR(top, (to.pos + to.rot * held).z() + 0.12, 0.005);
  const Eigen::Vector3d first = arc.front().pos + arc.front().rot * held - (from.pos + held);
  EXPECT_GT(first.z(), 3 * first.head<2>().norm());
  const Eigen::Vector3d last =
      (to.pos + to.rot * held) - (arc[arc.size() - 2].pos + arc[arc.size() - 2].rot * held);
  EXPECT_LT(last.z(), -3 * last.head<2>().norm());
}

TEST(CarryOverTest, TheArmCarriesThePalmOverAnArcBetweenTwoSideGraspsIntegration) {
  // two side-grasp poses 30 cm apart over the board's near part, both free, reached from the
  // raised hand; the arm starts at the first
  auto w = TableScene(Eigen::Vector3d(0.3, 0.5, 0));
  const mjModel* m = w->model();
  mjData* d = w->data();
  const ArmChain& arm = OpenTheHand(*w).arm;
  mjData* s = mj_makeData(m);
  mju_copy(s->qpos, d->qpos, m->nq);
  const Eigen::VectorXd via = RaiseVias(TabletopOptions{}).back();
  const std::vector<PalmPose> a =
      Around(world::TableToWorld(Eigen::Vector3d(-0.15, 0.2, 0.1)), 0.08);
  const std::vector<PalmPose> b =
      Around(world::TableToWorld(Eigen::Vector3d(0.15, 0.2, 0.1)), 0.08);
  auto free = [&](const PalmPose& p, Eigen::VectorXd* q) {
    const IkResult r = SolvePalmIk(m, s, arm, p, via, via);
    *q = r.q;
    return r.converged && ArmContacts(m, s, arm, r.q) == 0;
  };
  int k = 0;
  Eigen::VectorXd q0, q1;
  while (k < static_cast<int>(a.size()) && !(free(a[k], &q0) && free(b[k], &q1))) ++k;
  ASSERT_LT(k, static_cast<int>(a.size())) << "no side-grasp pose reached at both ends";
  arm.Set(d, q0);
  mj_forward(m, d);
  CarryOverOptions co;
  co.lift_m = {0.1};
  co.margin_m = 0;
  auto over = PlanCarryOver(m, d, s, arm, a[k], b[k], Eigen::Vector3d::Zero(), co);
  ASSERT_TRUE(over.ok()) << over.status();
  const Trajectory& t = over->trajectory;
  EXPECT_LT(t.Sample(t.duration_s()).qdot.norm(), 1e-6) << "it ends at rest";
  // the palm ends at the goal, and its path peaks 10 cm over the higher end
  double top = -1e9;
  for (double at = 0; at <= t.duration_s() + 1e-9; at += 0.01) {
    arm.Set(s, t.Sample(std::min(at, t.duration_s())).q);
    mj_kinematics(m, s);
    top = std::max(top, s->site_xpos[3 * arm.palm_site + 2]);
  }
  EXPECT_LT((Eigen::Vector3d(s->site_xpos + 3 * arm.palm_site) - b[k].pos).norm(), 0.006);
  EXPECT_NEAR(top, std::max(a[k].pos.z(), b[k].pos.z()) + 0.1, 0.01);
  // an arc that ends inside the board is refused, naming the pose
  PalmPose into = b[k];
  into.pos.z() = world::TableToWorld(Eigen::Vector3d(0.15, 0.2, -0.05)).z();
  auto blocked = PlanCarryOver(m, d, s, arm, a[k], into, Eigen::Vector3d::Zero(), co);
  ASSERT_FALSE(blocked.ok());
  EXPECT_NE(blocked.status().message().find("plan failure: palm pose"), std::string::npos)
      << blocked.status();
  mj_deleteData(s);
}

}  // namespace
}  // namespace simhuman::control::manip
