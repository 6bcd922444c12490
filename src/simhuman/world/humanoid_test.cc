#include "simhuman/world/humanoid.h"

#include <gtest/gtest.h>

#include <cmath>
#include <set>

#include "simhuman/world/embodiment.h"
#include "simhuman/world/health.h"
#include "simhuman/world/scene.h"
#include "simhuman/world/sim_world.h"
#include "simhuman/world/testing/mujoco_warnings.h"

namespace simhuman::world {
namespace {

constexpr double kMassTolKg = 0.5;

std::unique_ptr<SimWorld> Empty(double scale = 1.0) {
  core::SceneCatalog cat;
  auto w = SimWorld::Create(cat, {{0, 0, 0, scale}});
  EXPECT_TRUE(w.ok()) << w.status();
  return std::move(w).value();
}

TEST(HumanoidTest, DofsBodiesActuatorsAndNamedPoints) {
  long warnings0 = MujocoWarningCount();
  auto w = Empty();
  const mjModel* m = w->model();
  EXPECT_EQ(m->nu, kHumanoidDofs);
  EXPECT_EQ(m->nv, kHumanoidDofs + 6);
  EXPECT_EQ(m->nq, kHumanoidDofs + 7);
  EXPECT_EQ(m->nbody, kHumanoidBodies + 1);  // + world
  EXPECT_EQ(static_cast<int>(HumanoidJointNames().size()), kHumanoidDofs);
  for (int j = 0; j < m->njnt; ++j) {
    if (m->jnt_type[j] == mjJNT_HINGE) {
      EXPECT_TRUE(m->jnt_limited[j]) << j;
    }
  }
  for (core::BodyJoint bj : core::AllBodyJoints()) {
    EXPECT_GE(mj_name2id(m, mjOBJ_SITE, BodyPointSiteName(bj).c_str()), 0)
        << core::BodyJointName(bj);
  }
  EXPECT_EQ(MujocoWarningCount(), warnings0);
}

TEST(HumanoidTest, HumanProportionsAndMass) {
  auto w = Empty();
  EXPECT_NEAR(mj_getTotalmass(w->model()), 60.0, kMassTolKg);
  EXPECT_NEAR(HumanoidMassKg(1.0), 60.0, kMassTolKg);
  auto pts = w->BodyPoints(w->data(), 0);
  auto at = [&](core::BodyJoint j) { return pts[static_cast<int>(j)]; };
  // head centre ~1.57 m (top of head ~1.67 m), shoulders ~1.37 m, hips ~0.91 m, knees ~0.49 m
  EXPECT_NEAR(at(core::BodyJoint::kHead).z(), 1.57, 0.05);
  EXPECT_NEAR(at(core::BodyJoint::kLeftShoulder).z(), 1.37, 0.05);
  EXPECT_NEAR(at(core::BodyJoint::kLeftHip).z(), 0.91, 0.05);
  EXPECT_NEAR(at(core::BodyJoint::kLeftKnee).z(), 0.49, 0.05);
  EXPECT_GT(at(core::BodyJoint::kLeftHand).y(), 0.1);  // left is +y when facing +x
  EXPECT_LT(at(core::BodyJoint::kRightHand).y(), -0.1);
  EXPECT_NEAR(at(core::BodyJoint::kLeftFoot).z(), 0.04, 0.02);
}

TEST(HumanoidTest, ChildVariantScalesWithOneParameter) {
  auto w = Empty(0.7);
  EXPECT_NEAR(mj_getTotalmass(w->model()), 60.0 * 0.7 * 0.7 * 0.7, kMassTolKg);
  auto pts = w->BodyPoints(w->data(), 0);
  EXPECT_NEAR(pts[static_cast<int>(core::BodyJoint::kHead)].z(), 1.57 * 0.7, 0.05);
}

TEST(HumanoidTest, AScaledBodyIsDynamicallySimilarToTheAdultIntegration) {
  // times scale with sqrt(s): servo stiffness / inertia and damping / inertia must give the
  // adult's rates x 1/sqrt(s) (kp ~ s^4, damping ~ s^4.5, armature and inertias ~ s^5)
  auto adult = Empty(1.0), child = Empty(0.64);
  const mjModel* a = adult->model();
  const mjModel* c = child->model();
  const int knee = mj_name2id(a, mjOBJ_JOINT, "right_knee");
  const int act = mj_name2id(a, mjOBJ_ACTUATOR, "right_knee");
  ASSERT_GE(knee, 0);
  ASSERT_GE(act, 0);
  const int dof = a->jnt_dofadr[knee];
  const double s = 0.64;
  EXPECT_NEAR(c->actuator_gainprm[10 * act] / a->actuator_gainprm[10 * act], std::pow(s, 4), 1e-6);
  EXPECT_NEAR(c->dof_damping[dof] / a->dof_damping[dof], std::pow(s, 4.5), 1e-3);
  EXPECT_NEAR(c->dof_armature[dof] / a->dof_armature[dof], std::pow(s, 5), 1e-3);
  // the shank's inertia about its own axes scales as s^5 too
  const int shin = a->jnt_bodyid[knee];
  EXPECT_NEAR(c->body_inertia[3 * shin] / a->body_inertia[3 * shin], std::pow(s, 5), 0.02);
}

TEST(HumanoidTest, TwoAgentsHaveSeparateNames) {
  core::SceneCatalog cat;
  auto w = SimWorld::Create(cat, {{0, 0, 0, 1.0}, {2, 0, 0, 0.7}});
  ASSERT_TRUE(w.ok()) << w.status();
  EXPECT_EQ((*w)->num_agents(), 2);
  EXPECT_EQ((*w)->model()->nu, 2 * kHumanoidDofs);
  EXPECT_NE((*w)->agent(0).pelvis_body, (*w)->agent(1).pelvis_body);
}

TEST(HealthTest, NonFiniteStateEndsWithAReason) {
  testing::ScopedExpectMujocoWarnings expected;  // MuJoCo warns of the bad state it resets
  auto w = Empty();
  w->data()->qvel[3] = std::nan("");
  HealthReport r = w->Step();
  EXPECT_FALSE(r.ok());
  EXPECT_NE(r.reason.find("unstable"), std::string::npos) << r.reason;
}

TEST(HealthTest, RunawayVelocityIsUnstable) {
  testing::ScopedExpectMujocoWarnings expected;
  auto w = Empty();
  w->data()->qvel[10] = 1e6;
  HealthReport r = w->Step();
  EXPECT_FALSE(r.ok());
  EXPECT_NE(r.reason.find("unstable"), std::string::npos) << r.reason;
}

TEST(HealthTest, CleanStepsAreOk) {
  auto w = Empty();
  for (int i = 0; i < 50; ++i) ASSERT_TRUE(w->Step().ok());
}

TEST(ModelBuilderTest, RejectsBadPlacements) {
  core::SceneCatalog cat;
  EXPECT_FALSE(SimWorld::Create(cat, {}).ok());
  EXPECT_FALSE(SimWorld::Create(cat, {{std::nan(""), 0, 0, 1.0}}).ok());
  EXPECT_FALSE(SimWorld::Create(cat, {{0, 0, 0, 5.0}}).ok());
}

}  // namespace
}  // namespace simhuman::world

namespace simhuman::world {
namespace {

// the movable cylinder and sphere of tabletop_demo stay where they are put on the table
TEST(TabletopDemoTest, CylinderAndSphereRestOnTheTable) {
  constexpr double kSettleS = 1.0;
  constexpr double kDriftTolM = 0.01;
  core::StatusOr<SceneSpec> spec = LoadScene("tabletop_demo");
  ASSERT_TRUE(spec.ok());
  core::StatusOr<core::SceneCatalog> cat = BuildCatalog(*spec);
  ASSERT_TRUE(cat.ok());
  // the human stands well away so that nothing but gravity acts on the objects
  auto w = SimWorld::Create(*cat, {{-3.0, 0, 0, 1.0}});
  ASSERT_TRUE(w.ok()) << w.status();
  const mjModel* m = (*w)->model();
  std::vector<std::pair<int, Eigen::Vector3d>> start;
  for (const char* id : {"cylinder005", "sphere006", "box001"}) {
    int body = mj_name2id(m, mjOBJ_BODY, ("obj/" + std::string(id)).c_str());
    ASSERT_GE(body, 0) << id;
    start.push_back({body, Eigen::Vector3d::Zero()});
  }
  mj_forward(m, (*w)->data());
  for (auto& [body, pos] : start)
    pos = Eigen::Map<const Eigen::Vector3d>((*w)->data()->xpos + 3 * body);
  for (int i = 0; i < static_cast<int>(kSettleS / m->opt.timestep); ++i) (*w)->Step();
  for (const auto& [body, pos] : start) {
    Eigen::Vector3d now = Eigen::Map<const Eigen::Vector3d>((*w)->data()->xpos + 3 * body);
    EXPECT_LT((now - pos).norm(), kDriftTolM) << mj_id2name(m, mjOBJ_BODY, body);
  }
}

TEST(EmbodimentTest, KindsAreDataAndAnUnknownKindIsNamed) {
  ASSERT_FALSE(Embodiments().empty());
  EXPECT_EQ(Embodiments()[0].name, kDefaultAgentKind);
  core::StatusOr<const Embodiment*> bad = FindEmbodiment("robot");
  ASSERT_FALSE(bad.ok());
  EXPECT_NE(bad.status().message().find("valid agent kinds are: humanoid, humanoid_right_hand"),
            std::string::npos)
      << bad.status();
  // the default kind's catalog is the 15 standard points
  core::CatalogAgent plain = MakeCatalogAgent(**FindEmbodiment("humanoid"), 1.0);
  EXPECT_EQ(plain.body_points.Names(), core::BodyJointNames());
  core::CatalogAgent two = MakeCatalogAgent(**FindEmbodiment("humanoid_hands"), 0.8);
  EXPECT_EQ(two.body_points.size(), core::kNumBodyJoints + 6);
  EXPECT_DOUBLE_EQ(two.scale, 0.8);
  EXPECT_TRUE(two.body_points.Find("left thumb tip").has_value());
}

// the gripping kind adds one adhesion actuator per capsule hand, after the agent's hinge span,
// scaled with the body's mass; the plain kind has none
TEST(EmbodimentTest, GripKindAddsAnAdhesionActuatorPerHand) {
  auto w = SimWorld::Create(core::SceneCatalog(),
                            {{0, 0, 0, 1.0, "humanoid_grip"}, {2, 0, 0, 0.8, "humanoid"}});
  ASSERT_TRUE(w.ok()) << w.status();
  const mjModel* m = (*w)->model();
  EXPECT_EQ((*w)->agent(0).num_actuators(), kHumanoidDofs);
  EXPECT_EQ(m->nu, 2 * kHumanoidDofs + 2);
  for (const std::string& name : HumanoidGripActuatorNames()) {
    const int id = mj_name2id(m, mjOBJ_ACTUATOR, name.c_str());
    ASSERT_GE(id, 0) << name;
    EXPECT_EQ(m->actuator_trntype[id], mjTRN_BODY) << name;
    const std::string hand = name.substr(0, name.find('_')) + "_hand";
    EXPECT_EQ(m->actuator_trnid[2 * id], mj_name2id(m, mjOBJ_BODY, hand.c_str())) << name;
    EXPECT_DOUBLE_EQ(m->actuator_gainprm[id * mjNGAIN], kCarryGripN) << name;
    EXPECT_EQ(mj_name2id(m, mjOBJ_ACTUATOR, ("h1/" + name).c_str()), -1) << name;
  }
}

// agents of different kinds in one model: tables sized from the model, spans side by side
TEST(EmbodimentTest, AgentTablesComeFromTheCompiledModel) {
  std::vector<AgentSpec> agents = {{0, 0, 0, 1.0, "humanoid"},
                                   {2, 0, 0, 1.0, "humanoid_hands"},
                                   {4, 0, 0, 0.7, "humanoid_right_hand"}};
  auto w = SimWorld::Create(core::SceneCatalog(), agents);
  ASSERT_TRUE(w.ok()) << w.status();
  const mjModel* m = (*w)->model();
  const int extra = kHandDofs;
  EXPECT_EQ((*w)->agent(0).num_actuators(), kHumanoidDofs);
  EXPECT_EQ((*w)->agent(1).num_actuators(), kHumanoidDofs + 2 * extra);
  EXPECT_EQ((*w)->agent(2).num_actuators(), kHumanoidDofs + extra);
  EXPECT_EQ(m->nu, 3 * kHumanoidDofs + 3 * extra);
  std::set<int> seen;
  for (int a = 0; a < 3; ++a) {
    const AgentIndex& ix = (*w)->agent(a);
    for (int j = 0; j < ix.num_actuators(); ++j) {
      EXPECT_TRUE(seen.insert(ix.actuator[j]).second) << "actuator shared: agent " << a;
      // each actuator drives the hinge the index pairs it with
      EXPECT_EQ(m->jnt_qposadr[m->actuator_trnid[2 * ix.actuator[j]]], ix.hinge_qpos[j]);
    }
    EXPECT_EQ(ix.num_body_points(), (*w)->catalog().agents[a].body_points.size());
  }
  EXPECT_EQ((*w)->catalog().agents[1].kind, "humanoid_hands");
  // the palm point sits in front of the hand point, within a hand's length
  std::vector<Eigen::Vector3d> pts;
  (*w)->AllBodyPoints((*w)->data(), 2, &pts);
  const int palm = static_cast<int>(*(*w)->catalog().agents[2].body_points.Find("right palm"));
  const double d = (pts[palm] - pts[static_cast<int>(core::BodyJoint::kRightHand)]).norm();
  EXPECT_GT(d, 0.01);
  EXPECT_LT(d, 0.1);
  // an unknown kind is refused by name
  auto bad = SimWorld::Create(core::SceneCatalog(), {{0, 0, 0, 1.0, "robot"}});
  ASSERT_FALSE(bad.ok());
  EXPECT_NE(bad.status().message().find("human 0: unknown agent kind 'robot'"), std::string::npos)
      << bad.status();
}

}  // namespace
}  // namespace simhuman::world
