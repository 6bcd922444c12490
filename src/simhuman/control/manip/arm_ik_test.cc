#include "simhuman/control/manip/arm_ik.h"

#include <gtest/gtest.h>

#include <cmath>
#include <memory>

#include "simhuman/world/objects.h"
#include "simhuman/world/sim_world.h"

namespace simhuman::control::manip {
namespace {

// a human seated at a table (its near edge 7.5 cm past the seat's front edge, over the thighs),
// right hand dexterous, pelvis held; a cylinder on the table
struct Table {
  std::unique_ptr<world::SimWorld> world;
  double top_z = 0, edge_x = 0;
};

Table SeatedAtTable(const std::string& kind = "humanoid_right_hand") {
  const double seat_d = world::DefaultSizes("chair").at("seat_depth");
  const double table_d = world::DefaultSizes("table").at("depth");
  Table t;
  t.top_z = world::DefaultSizes("table").at("height");
  t.edge_x = seat_d / 2 + 0.075;  // the chest ~19 cm from the table's edge
  core::SceneCatalog scene;
  auto spec = [](const char* id, const char* type, Eigen::Vector3d pos, double yaw) {
    world::ObjectSpec o;
    o.id = id;
    o.type = type;
    o.pos = pos;
    o.yaw_rad = yaw;
    return o;
  };
  world::ObjectSpec table = spec("table000", "table", {t.edge_x + table_d / 2, 0, 0}, M_PI);
  world::ObjectSpec chair = spec("chair001", "chair", {0, 0, 0}, 0);
  world::ObjectSpec can = spec("cylinder002", "cylinder", {t.edge_x + 0.2, -0.2, t.top_z}, 0);
  can.color = "red";
  can.size = {{"radius", 0.035}, {"height", 0.15}};
  can.mass_kg = 2.0;
  for (const auto& one : {table, chair, can}) {
    auto o = world::BuildObject(one);
    EXPECT_TRUE(o.ok()) << o.status();
    scene.objects.push_back(*o);
  }
  world::AgentSpec human;
  human.kind = kind;
  human.seated_pelvis_z =
      world::DefaultSizes("chair").at("seat_height") + world::SeatedPelvisAboveSeat(1.0);
  human.hold_pelvis = true;
  auto w = world::SimWorld::Create(scene, {human});
  EXPECT_TRUE(w.ok()) << w.status();
  t.world = std::move(*w);
  return t;
}

TEST(ArmIkTest, TheArmChainIsSevenHingesFromShoulderToWrist) {
  Table t = SeatedAtTable();
  auto arm = MakeArmChain(*t.world, 0, true);
  ASSERT_TRUE(arm.ok()) << arm.status();
  EXPECT_EQ(arm->finger_actuators.size(), 22u);
  for (int i = 0; i < ArmChain::kDofs; ++i) EXPECT_LT(arm->lo[i], arm->hi[i]);
  // 3 arm bodies plus the hand's 17 (palm halves, 4 fingers x 3, thumb 3 minus the hand's own)
  EXPECT_GE(arm->bodies.size(), 18u);
  // no left dexterous hand on this kind, and none at all on the plain humanoid
  auto left = MakeArmChain(*t.world, 0, false);
  ASSERT_FALSE(left.ok());
  EXPECT_NE(left.status().message().find("no dexterous left hand"), std::string::npos);
}

// the seated human's right arm, a scratch mjData at the world's start and the arm's angles
// there, and a grasp centre on the table
struct ArmAtTable {
  Table t = SeatedAtTable();
  ArmChain arm = *MakeArmChain(*t.world, 0, true);
  const mjModel* m = t.world->model();
  mjData* d = mj_makeData(m);
  Eigen::VectorXd rest;
  Eigen::Vector3d centre{t.edge_x + 0.2, -0.2, t.top_z + 0.07};
  ArmAtTable() {
    mju_copy(d->qpos, t.world->data()->qpos, m->nq);
    rest = arm.Get(d);
  }
  ~ArmAtTable() { mj_deleteData(d); }
};

TEST(ArmIkTest, ThePalmReachesASideGraspOfAnObjectOnTheTable) {
  ArmAtTable at;
  auto& [t, arm, m, d, rest, centre] = at;
  int solved = 0, free = 0;
  for (int k = 0; k < 8; ++k) {
    const double yaw = -M_PI / 2 + k * M_PI / 8;  // approaches from the right and the front
    const PalmPose target = SideGraspPose(centre, 0.09, yaw, true);
    const IkResult r = SolvePalmIk(m, d, arm, target, rest, rest);
    solved += r.converged;
    if (r.converged) {
      // the result is what it claims
      EXPECT_LT((Eigen::Vector3d(d->site_xpos + 3 * arm.palm_site) - target.pos).norm(), 0.006);
      for (int i = 0; i < ArmChain::kDofs; ++i) {
        EXPECT_GE(r.q[i], arm.lo[i] - 1e-9);
        EXPECT_LE(r.q[i], arm.hi[i] + 1e-9);
      }
      free += ArmContacts(m, d, arm, r.q) == 0;
    }
  }
  EXPECT_GE(solved, 5) << "of 8 approach directions";  // 6 measured
  EXPECT_GE(free, 2);  // 3 measured: the forearm often rests on the table edge
  // a point 1.5 m away is out of reach: the solver says so and returns its best
  const IkResult far =
      SolvePalmIk(m, d, arm, SideGraspPose({1.8, -0.2, 0.8}, 0.04, 0, true), rest, rest);
  EXPECT_FALSE(far.converged);
  EXPECT_GT(far.pos_err_m, 0.5);
}

// an upright object's yaw in the hand does not matter: a pose the arm cannot reach at its own
// turn is reached at another turn about the object's vertical, and only turned
TEST(ArmIkTest, APoseFreeInYawIsReachedAtSomeTurnAboutItsVertical) {
  ArmAtTable at;
  auto& [t, arm, m, d, rest, centre] = at;
  int fixed_misses = 0;
  for (int k = 0; k < 16; ++k) {
    const double yaw = -M_PI + k * M_PI / 8;
    PalmPose target = SideGraspPose(centre, 0.09, yaw, true);
    if (SolvePalmIk(m, d, arm, target, rest, rest).converged) continue;
    ++fixed_misses;
    target.yaw_free_about = centre;
    const IkResult r = SolvePalmIk(m, d, arm, target, rest, rest);
    ASSERT_TRUE(r.converged) << "approach yaw " << yaw;
    arm.Set(d, r.q);
    mj_kinematics(m, d);
    const Eigen::Vector3d palm(d->site_xpos + 3 * arm.palm_site);
    EXPECT_NEAR(palm.z(), target.pos.z(), 0.006);
    EXPECT_NEAR((palm - centre).head<2>().norm(), (target.pos - centre).head<2>().norm(), 0.006);
    Eigen::Matrix3d hand;
    for (int i = 0; i < 9; ++i) hand(i / 3, i % 3) = d->xmat[9 * arm.hand_body + i];
    // the hand is the target's rotation turned about the vertical only
    EXPECT_GT((hand * target.rot.transpose())(2, 2), std::cos(0.07)) << "approach yaw " << yaw;
  }
  EXPECT_GE(fixed_misses, 4) << "the test needs turns the arm cannot reach as given";
}

TEST(ArmIkTest, ThePalmInsideTheTableIsAContact) {
  ArmAtTable at;
  EXPECT_EQ(ArmContacts(at.m, at.d, at.arm, at.rest), 0) << "the seated rest pose is free";
  const PalmPose sunk =
      SideGraspPose({at.t.edge_x + 0.25, 0.1, at.t.top_z - 0.03}, 0.04, -M_PI / 4, true);
  const IkResult r = SolvePalmIk(at.m, at.d, at.arm, sunk, at.rest, at.rest);
  EXPECT_GT(ArmContacts(at.m, at.d, at.arm, r.q), 0);
}

TEST(ArmIkTest, ATopGraspPoseHasThePalmDownOverTheTopAndTheFingersAlongTheYaw) {
  const Eigen::Vector3d top(1.0, -0.1, 0.85);
  for (bool right : {true, false}) {
    for (double yaw : {0.0, 0.7, -2.0}) {
      const PalmPose p = TopGraspPose(top, 0.04, yaw, right, 0.03);
      EXPECT_TRUE((p.rot.transpose() * p.rot).isIdentity(1e-12));
      EXPECT_NEAR(p.rot.determinant(), 1.0, 1e-12);
      // out of the palm: the right palm faces its frame's +y, the left its -y; both face down
      const Eigen::Vector3d palm_out = right ? p.rot.col(1) : Eigen::Vector3d(-p.rot.col(1));
      EXPECT_TRUE(palm_out.isApprox(Eigen::Vector3d(0, 0, -1), 1e-12));
      // fingers (hand -z) horizontal along the yaw; the thumb (hand +x) to the fingers' left for
      // the right hand (palm down), to their right for the left hand
      const Eigen::Vector3d f(std::cos(yaw), std::sin(yaw), 0);
      EXPECT_TRUE((-p.rot.col(2)).isApprox(f, 1e-12));
      const Eigen::Vector3d left_of_f(-f.y(), f.x(), 0);
      EXPECT_TRUE(p.rot.col(0).isApprox(right ? left_of_f : Eigen::Vector3d(-left_of_f), 1e-12));
      // the palm point: 4 cm above the top, 3 cm back from it along the fingers
      EXPECT_TRUE(p.pos.isApprox(top + Eigen::Vector3d(0, 0, 0.04) - 0.03 * f, 1e-12));
    }
  }
}

}  // namespace
}  // namespace simhuman::control::manip
