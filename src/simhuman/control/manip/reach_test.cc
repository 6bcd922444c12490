#include "simhuman/control/manip/reach.h"

#include <gtest/gtest.h>

#include <cmath>
#include <memory>

#include "simhuman/control/manip/grasp_task.h"
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
  const GraspIndex gi = *MakeGraspIndex(*w, 0, true);
  const ArmChain& arm = gi.arm;
  SetOpenHand(gi, d);
  mj_forward(m, d);
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

}  // namespace
}  // namespace simhuman::control::manip
