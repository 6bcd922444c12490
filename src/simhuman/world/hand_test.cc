#include "simhuman/world/hand.h"

#include <gtest/gtest.h>
#include <mujoco/mujoco.h>

#include <Eigen/Core>
#include <cmath>
#include <memory>
#include <string>

#include "simhuman/world/objects.h"
#include "simhuman/world/sim_world.h"

namespace simhuman::world {
namespace {

struct Model {
  std::unique_ptr<SimWorld> world;
  const mjModel* m() const { return world->model(); }
  mjData* d() const { return world->data(); }
  int Site(const std::string& name) const { return mj_name2id(m(), mjOBJ_SITE, name.c_str()); }
  int Joint(const std::string& name) const { return mj_name2id(m(), mjOBJ_JOINT, name.c_str()); }
  Eigen::Vector3d SitePos(const std::string& name) const {
    const int s = Site(name);
    EXPECT_GE(s, 0) << name;
    return Eigen::Vector3d(d()->site_xpos + 3 * std::max(s, 0));
  }
  // hand-frame coordinates of a world point (the hand body's frame)
  Eigen::Vector3d InHand(const std::string& side, const Eigen::Vector3d& p) const {
    const int b = mj_name2id(m(), mjOBJ_BODY, (side + "_hand").c_str());
    Eigen::Map<const Eigen::Matrix<double, 3, 3, Eigen::RowMajor>> r(d()->xmat + 9 * b);
    return r.transpose() * (p - Eigen::Vector3d(d()->xpos + 3 * b));
  }
  // every hinge of one side's hand at `frac` of its range
  void Close(const std::string& side, double frac) const {
    for (const HandJoint& j : HandJoints()) {
      if (std::string(j.name).rfind("forearm", 0) == 0 ||
          std::string(j.name).rfind("wrist", 0) == 0)
        continue;
      const int id = Joint(side + "_" + j.name);
      const double lo = std::max(0.0, j.lo_deg);
      d()->qpos[m()->jnt_qposadr[id]] = (lo + frac * (j.hi_deg - lo)) * M_PI / 180;
    }
    mj_kinematics(m(), d());
  }
};

Model Build(const std::string& kind) {
  auto w = SimWorld::Create(core::SceneCatalog(), {{0, 0, 0, 1.0, kind}});
  EXPECT_TRUE(w.ok()) << w.status();
  Model out{std::move(*w)};
  mj_kinematics(out.m(), out.d());
  return out;
}

TEST(HandTest, SevenDofArmAndTwentyTwoDofHandOfAdultSize) {
  EXPECT_EQ(static_cast<int>(HandJoints().size()), kHandDofs);
  EXPECT_EQ(kHandFingerDofs, 22);
  Model h = Build("humanoid_right_hand");
  const AgentIndex& ix = h.world->agent(0);
  EXPECT_EQ(ix.num_actuators(), kHumanoidDofs + kHandDofs);
  // the arm from the shoulder to the palm: shoulder 3, elbow 1, forearm 1, wrist 2
  int arm = 0;
  for (const char* j : {"right_shoulder_x", "right_shoulder_y", "right_shoulder_z", "right_elbow",
                        "right_forearm_rot", "right_wrist_flex", "right_wrist_dev"}) {
    arm += h.Joint(j) >= 0;
  }
  EXPECT_EQ(arm, 7);
  // wrist to middle fingertip about 19 cm; palm about 8-9 cm wide
  const Eigen::Vector3d tip = h.InHand("right", h.SitePos("right_middle_tip"));
  EXPECT_NEAR(-tip.z(), 0.19, 0.01);
  const Eigen::Vector3d index = h.InHand("right", h.SitePos("right_index_tip"));
  const Eigen::Vector3d little = h.InHand("right", h.SitePos("right_little_tip"));
  EXPECT_NEAR(index.x() - little.x(), 0.062, 0.01);
  EXPECT_NEAR(HandMassKg(1.0), 0.36, 1e-9);
  // one touch geom per phalanx and palm half
  for (const std::string& part : HandTouchParts()) {
    EXPECT_GE(mj_name2id(h.m(), mjOBJ_GEOM, ("right_" + part + "_geom").c_str()), 0) << part;
  }
  EXPECT_EQ(HandTouchParts().size(), 17u);
}

TEST(HandTest, ClosingCurlsTheFingersIntoThePalmAndTheThumbOpposesThem) {
  Model h = Build("humanoid_right_hand");
  const Eigen::Vector3d open_thumb = h.InHand("right", h.SitePos("right_thumb_tip"));
  const Eigen::Vector3d open_index = h.InHand("right", h.SitePos("right_index_tip"));
  h.Close("right", 0.6);
  for (const std::string& tip : HandTipSites()) {
    const Eigen::Vector3d p = h.InHand("right", h.SitePos("right_" + tip));
    EXPECT_GT(p.y(), 0.02) << tip << " should be on the palm side";
  }
  // the middle fingertip folds back toward the palm
  EXPECT_GT(h.InHand("right", h.SitePos("right_middle_tip")).z(), -0.15);
  // the thumb swings across in front of the palm (opposition): toward the little finger's side
  const Eigen::Vector3d closed_thumb = h.InHand("right", h.SitePos("right_thumb_tip"));
  EXPECT_LT(closed_thumb.x(), open_thumb.x() - 0.03);
  EXPECT_GT(closed_thumb.y(), 0.01);
  EXPECT_GT(open_index.y(), -0.01);
}

TEST(HandTest, TheLeftHandIsTheMirrorImageOfTheRight) {
  Model h = Build("humanoid_hands");
  h.Close("right", 0.4);
  h.Close("left", 0.4);
  for (const std::string& tip : HandTipSites()) {
    const Eigen::Vector3d r = h.SitePos("right_" + tip);
    const Eigen::Vector3d l = h.SitePos("left_" + tip);
    EXPECT_NEAR(r.x(), l.x(), 1e-6) << tip;
    EXPECT_NEAR(r.y(), -l.y(), 1e-6) << tip;
    EXPECT_NEAR(r.z(), l.z(), 1e-6) << tip;
  }
  // the wrist hinges mirror too
  for (const char* j : {"forearm_rot", "wrist_flex", "wrist_dev"}) {
    h.d()->qpos[h.m()->jnt_qposadr[h.Joint(std::string("right_") + j)]] = 0.3;
    h.d()->qpos[h.m()->jnt_qposadr[h.Joint(std::string("left_") + j)]] = 0.3;
  }
  mj_kinematics(h.m(), h.d());
  const Eigen::Vector3d r = h.SitePos("right_middle_tip"), l = h.SitePos("left_middle_tip");
  EXPECT_NEAR(r.x(), l.x(), 1e-6);
  EXPECT_NEAR(r.y(), -l.y(), 1e-6);
}

TEST(HandTest, AHalfClosedHandStaysStillWhenSimulated) {
  Model h = Build("humanoid_right_hand");
  // no gravity, the arm held out sideways (clear of the thigh): only the hand's servos act
  const AgentIndex& ix = h.world->agent(0);
  h.world->mutable_model()->opt.gravity[2] = 0;
  const int shoulder = h.Joint("right_shoulder_x");
  for (int j = 0; j < ix.num_actuators(); ++j) {
    const HandJoint* hj = j >= kHumanoidDofs ? &HandJoints()[j - kHumanoidDofs] : nullptr;
    const double target =
        hj ? (std::max(0.0, hj->lo_deg) + 0.5 * (hj->hi_deg - std::max(0.0, hj->lo_deg))) * M_PI /
                 180
           : 0.0;
    h.d()->ctrl[ix.actuator[j]] = target;
    if (ix.hinge_qpos[j] == h.m()->jnt_qposadr[shoulder]) h.d()->ctrl[ix.actuator[j]] = 1.0;
  }
  for (int k = 0; k < 400; ++k) {
    HealthReport r = h.world->Step();
    ASSERT_TRUE(r.ok()) << r.reason;
  }
  for (int j = kHumanoidDofs + kHandArmDofs; j < ix.num_actuators(); ++j) {
    EXPECT_NEAR(h.d()->qpos[ix.hinge_qpos[j]], h.d()->ctrl[ix.actuator[j]], 0.05)
        << HandJoints()[j - kHumanoidDofs].name;
    EXPECT_LT(std::abs(h.d()->qvel[ix.hinge_qvel[j]]), 0.05);
  }
}

}  // namespace
}  // namespace simhuman::world

namespace simhuman::world {
namespace {

// a human seated on a chair with the pelvis held (the tabletop set-up) stays seated while its
// servos hold the seated pose
TEST(SeatedHumanTest, AHeldSeatedHumanStaysOnTheChair) {
  ObjectSpec chair;
  chair.id = "chair000";
  chair.type = "chair";
  core::SceneCatalog scene;
  scene.objects.push_back(*BuildObject(chair));
  AgentSpec human;
  human.kind = "humanoid_right_hand";
  human.x = 0.02;
  human.seated_pelvis_z = DefaultSizes("chair").at("seat_height") + SeatedPelvisAboveSeat(1.0);
  human.hold_pelvis = true;
  auto w = SimWorld::Create(scene, {human});
  ASSERT_TRUE(w.ok()) << w.status();
  const AgentIndex& ix = (*w)->agent(0);
  const mjData* d = (*w)->data();
  const Eigen::Vector3d pelvis0(d->xpos + 3 * ix.pelvis_body);
  const Eigen::Vector3d head0(d->xpos + 3 * ix.head_body);
  EXPECT_NEAR(pelvis0.z(), human.seated_pelvis_z, 1e-6);
  const int knee = mj_name2id((*w)->model(), mjOBJ_JOINT, "right_knee");
  for (int k = 0; k < 400; ++k) ASSERT_TRUE((*w)->Step().ok());
  const Eigen::Vector3d pelvis(d->xpos + 3 * ix.pelvis_body);
  const Eigen::Vector3d head(d->xpos + 3 * ix.head_body);
  EXPECT_LT((pelvis - pelvis0).norm(), 0.01);
  EXPECT_LT((head - head0).norm(), 0.03);
  EXPECT_GT(head.z(), 1.0);  // sitting upright: the head's base well above the seat
  // the knees stay bent over the chair's front edge
  EXPECT_NEAR(d->qpos[(*w)->model()->jnt_qposadr[knee]], M_PI / 2, 0.15);
}

}  // namespace
}  // namespace simhuman::world
