#include "simhuman/eval/suites.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <set>

#include "simhuman/core/rng.h"
#include "simhuman/eval/episode.h"
#include "simhuman/eval/reachability.h"
#include "simhuman/plan/validate.h"

namespace simhuman::eval {
namespace {

using ::testing::HasSubstr;

constexpr int kSamples = 120;  // episodes drawn per range test
constexpr double kTol = 1e-9;  // metres / radians
constexpr double kDegToRad = M_PI / 180.0;

EpisodeSpec Make(const std::string& suite, uint64_t seed) {
  core::StatusOr<EpisodeSpec> s = MakeEpisodeSpec(suite, seed);
  EXPECT_TRUE(s.ok()) << s.status();
  return s.ok() ? *s : EpisodeSpec{};
}

// everything a spec holds, as one comparable value
nlohmann::json Fingerprint(const EpisodeSpec& s) {
  return {{"scene", world::SceneToJson(s.scene)},
          {"plan", s.plan},
          {"variant", s.variant},
          {"extra", static_cast<int>(s.extra)},
          {"object", s.object_id},
          {"joint", static_cast<int>(s.joint)}};
}

// the human's start in the frame of the object (x front, y left)
Eigen::Vector2d HumanInObjectFrame(const EpisodeSpec& s) {
  const world::ObjectSpec& o = s.scene.objects.at(0);
  Eigen::Vector2d d = s.scene.humans.at(0).pos_xy - o.pos.head<2>();
  double c = std::cos(-o.yaw_rad), sn = std::sin(-o.yaw_rad);
  return Eigen::Vector2d(c * d.x() - sn * d.y(), sn * d.x() + c * d.y());
}

core::CatalogObject Built(const EpisodeSpec& s) {
  core::StatusOr<core::CatalogObject> o = world::BuildObject(s.scene.objects.at(0));
  EXPECT_TRUE(o.ok()) << o.status();
  return o.ok() ? *o : core::CatalogObject{};
}

// the plan grounds against the scene and passes the reach check
void ExpectRunnable(const EpisodeSpec& s) {
  core::StatusOr<core::SceneCatalog> catalog = world::BuildCatalog(s.scene);
  ASSERT_TRUE(catalog.ok()) << catalog.status();
  core::StatusOr<plan::ContactChain> chain = plan::ParseContactChainJson(s.plan, "suite");
  ASSERT_TRUE(chain.ok()) << chain.status();
  ASSERT_TRUE(plan::ValidateAndGround(*chain, *catalog).ok());
  EXPECT_TRUE(CheckWithinReach(*chain, *catalog, s.scene.humans).ok()) << s.plan.dump();
  EXPECT_TRUE(AgentSpecs(s.scene).ok());
}

TEST(SuitesTest, RegistryNamesAreUniqueAndPlanSuitesHaveGenerators) {
  std::set<std::string> names;
  for (const SuiteDef& s : Suites()) {
    EXPECT_TRUE(names.insert(s.name).second) << s.name;
    EXPECT_EQ(FindSuite(s.name), &s);
    EXPECT_EQ(s.make != nullptr, s.controller == SuiteController::kMpc) << s.name;
    EXPECT_FALSE(s.description.empty()) << s.name;
  }
  EXPECT_EQ(SuiteNames().size(), Suites().size());
  EXPECT_EQ(FindSuite("Sit"), nullptr);
  EXPECT_EQ(FindSuite("dance"), nullptr);
  core::StatusOr<EpisodeSpec> walk = MakeEpisodeSpec("walk", 1);
  ASSERT_FALSE(walk.ok());
  EXPECT_NE(walk.status().message().find("not a plan suite; valid are: sit, lie"),
            std::string::npos)
      << walk.status();
}

TEST(SuitesTest, SameSeedSameEpisodeWhateverRanBefore) {
  for (const SuiteDef& def : Suites()) {
    if (!def.make) continue;
    const std::string& name = def.name;
    const std::string& suite = name;
    nlohmann::json first = Fingerprint(Make(suite, 42));
    Make(suite, 7);
    Make("lie", 42);
    EXPECT_EQ(Fingerprint(Make(suite, 42)), first) << name;
    EXPECT_NE(Fingerprint(Make(suite, 43)), first) << name;
    EXPECT_EQ(Make(suite, 42).seed, 42u);
  }
}

TEST(SuitesTest, SitProtocolRanges) {
  std::set<std::string> types;
  for (int i = 0; i < kSamples; ++i) {
    EpisodeSpec s = Make("sit", core::DeriveSeed(1, i));
    ASSERT_EQ(s.scene.objects.size(), 1u);
    ASSERT_EQ(s.scene.humans.size(), 1u);
    const world::ObjectSpec& o = s.scene.objects[0];
    types.insert(o.type);
    EXPECT_EQ(s.variant, o.type);
    EXPECT_EQ(s.object_id, o.id);
    EXPECT_EQ(s.extra, ExtraCheck::kNone);
    EXPECT_TRUE(o.pos.isZero());
    auto [lo, hi] = Built(s).LocalBounds();
    Eigen::Vector2d local = HumanInObjectFrame(s);
    EXPECT_GE(local.x() - hi.x(), 0.30 - kTol);
    EXPECT_LE(local.x() - hi.x(), 0.50 + kTol);
    double lateral = o.type == "sofa" ? 0.5 : 0.08;
    EXPECT_LE(std::abs(local.y() - 0.5 * (lo.y() + hi.y())), lateral + kTol) << o.type;
    // back to the seat: facing the object's front, +-15 degrees
    EXPECT_LE(std::abs(core::WrapAngle(s.scene.humans[0].yaw_rad - o.yaw_rad)),
              15 * kDegToRad + kTol);
    ASSERT_EQ(s.plan["steps"].size(), 1u);
    EXPECT_EQ(s.plan["steps"][0]["pairs"][0]["part"], "seat surface");
    EXPECT_EQ(s.plan["steps"][0]["pairs"][0]["joint"], "pelvis");
    ExpectRunnable(s);
  }
  EXPECT_EQ(types, (std::set<std::string>{"chair", "armchair", "sofa", "stool", "high_stool"}));
}

// stand-up: seated (posture "sit") on the seat or a bed's mattress, within 0.22 m of its front
// edge, facing out; one get-close step to the front; the scene seats the human
TEST(SuitesTest, StandUpStartsSeatedFacingOutAndGetsCloseToTheFront) {
  std::set<std::string> types;
  for (int i = 0; i < kSamples; ++i) {
    EpisodeSpec s = Make("stand-up", core::DeriveSeed(1, i));
    ASSERT_EQ(s.scene.objects.size(), 1u);
    ASSERT_EQ(s.scene.humans.size(), 1u);
    const world::ObjectSpec& o = s.scene.objects[0];
    types.insert(o.type);
    EXPECT_EQ(s.variant, o.type);
    EXPECT_EQ(s.scene.humans[0].posture, "sit");
    const core::CatalogObject built = Built(s);
    const core::CatalogPart* seat = built.FindPart(o.type == "bed" ? "mattress" : "seat surface");
    ASSERT_NE(seat, nullptr) << o.type;
    auto [lo, hi] = core::ShapesBounds(seat->shapes);
    const Eigen::Vector2d local = HumanInObjectFrame(s);
    EXPECT_LE(hi.x() - local.x(), 0.22 + kTol) << o.type;
    EXPECT_GT(hi.x() - local.x(), 0.0) << o.type;
    EXPECT_LE(std::abs(core::WrapAngle(s.scene.humans[0].yaw_rad - o.yaw_rad)),
              5 * kDegToRad + kTol);
    ASSERT_EQ(s.plan["steps"].size(), 1u);
    EXPECT_EQ(s.plan["steps"][0]["pairs"][0]["part"], "none");
    EXPECT_EQ(s.plan["steps"][0]["pairs"][0]["direction"], "front");
    ExpectRunnable(s);
  }
  EXPECT_EQ(types, (std::set<std::string>{"chair", "armchair", "sofa", "stool", "bed"}));
}

// get-up: the lie suite's episode (same start, same two steps) plus a stand-up step from the bed
TEST(SuitesTest, GetUpIsTheLieSuitePlusAStandUpFromTheBed) {
  for (int i = 0; i < kSamples; ++i) {
    const EpisodeSpec lie = Make("lie", core::DeriveSeed(3, i));
    const EpisodeSpec s = Make("get-up", core::DeriveSeed(3, i));
    ASSERT_EQ(s.scene.objects.size(), 1u);
    EXPECT_EQ(s.scene.objects[0].type, "bed");
    EXPECT_EQ(s.scene.humans[0].pos_xy, lie.scene.humans[0].pos_xy);
    EXPECT_EQ(s.scene.humans[0].posture, "stand");
    ASSERT_EQ(s.plan["steps"].size(), 3u);
    EXPECT_EQ(s.plan["steps"][0], lie.plan["steps"][0]);
    EXPECT_EQ(s.plan["steps"][1], lie.plan["steps"][1]);
    EXPECT_EQ(s.plan["steps"][2]["pairs"][0]["part"], "none");
    EXPECT_EQ(s.plan["steps"][2]["pairs"][0]["direction"], "front");
    EXPECT_EQ(s.plan["steps"][2]["pairs"][0]["object"], s.scene.objects[0].id);
    ExpectRunnable(s);
  }
}

TEST(SuitesTest, LieProtocolRanges) {
  for (int i = 0; i < kSamples; ++i) {
    EpisodeSpec s = Make("lie", core::DeriveSeed(2, i));
    const world::ObjectSpec& o = s.scene.objects.at(0);
    EXPECT_EQ(o.type, "bed");
    EXPECT_EQ(s.extra, ExtraCheck::kLieAlongBed);
    EXPECT_EQ(s.object_id, o.id);
    auto [lo, hi] = Built(s).LocalBounds();
    Eigen::Vector2d local = HumanInObjectFrame(s);
    EXPECT_GE(local.x() - hi.x(), 0.30 - kTol);
    EXPECT_LE(local.x() - hi.x(), 0.45 + kTol);
    // 0.65 m +- 0.1 m from the pillow's centre towards the foot end
    const core::CatalogObject bed = Built(s);
    auto [plo, phi] = core::ShapesBounds(bed.FindPart("pillow")->shapes);
    double pillow_y = 0.5 * (plo.y() + phi.y());
    EXPECT_LE(std::abs(std::abs(local.y() - pillow_y) - 0.65), 0.10 + kTol);
    EXPECT_LE(std::abs(core::WrapAngle(s.scene.humans[0].yaw_rad - o.yaw_rad)),
              15 * kDegToRad + kTol);
    ASSERT_EQ(s.plan["steps"].size(), 2u);
    EXPECT_EQ(s.plan["steps"][0]["pairs"][1]["contact"], "not contact");
    EXPECT_EQ(s.plan["steps"][1]["pairs"][1]["contact"], "contact");
    EXPECT_EQ(s.plan["steps"][1]["pairs"][1]["part"], "pillow");
    ExpectRunnable(s);
  }
}

TEST(SuitesTest, ReachProtocolRanges) {
  std::map<std::string, int> hands;
  for (int i = 0; i < kSamples; ++i) {
    EpisodeSpec s = Make("reach", core::DeriveSeed(3, i));
    const world::ObjectSpec& m = s.scene.objects.at(0);
    const world::HumanSpec& h = s.scene.humans.at(0);
    EXPECT_EQ(m.type, kMarkerType);
    EXPECT_EQ(s.extra, ExtraCheck::kHandAtPoint);
    ++hands[s.variant];
    bool left = s.variant == "left hand";
    EXPECT_EQ(s.joint, left ? core::BodyJoint::kLeftHand : core::BodyJoint::kRightHand);
    Eigen::Vector2d d = m.pos.head<2>() - h.pos_xy;
    double c = std::cos(-h.yaw_rad), sn = std::sin(-h.yaw_rad);
    double forward = c * d.x() - sn * d.y(), lateral = sn * d.x() + c * d.y();
    EXPECT_GE(forward, 0.25 - kTol);
    EXPECT_LE(forward, 0.55 + kTol);
    double outward = left ? lateral : -lateral;  // towards the reaching hand's side
    EXPECT_GE(outward, -0.10 - kTol);
    EXPECT_LE(outward, 0.35 + kTol);
    EXPECT_GE(m.pos.z(), 0.7 - kTol);
    EXPECT_LE(m.pos.z(), 1.5 + kTol);
    const auto& pair = s.plan["steps"][0]["pairs"][0];
    EXPECT_EQ(pair["part"], kMarkerPart);
    EXPECT_EQ(pair["joint"], s.variant);
    ExpectRunnable(s);
  }
  EXPECT_EQ(hands.size(), 2u);
  EXPECT_GT(hands["left hand"], kSamples / 4);
}

TEST(SuitesTest, ScenePlanSimpleIsShortSingleObjectAndNear) {
  std::set<std::string> kinds;
  for (int i = 0; i < kSamples; ++i) {
    EpisodeSpec s = Make("sceneplan-simple", core::DeriveSeed(4, i));
    EXPECT_EQ(s.scene.objects.size(), 1u);
    EXPECT_LE(s.plan["steps"].size(), 3u);
    EXPECT_EQ(s.extra, ExtraCheck::kNone);
    bool bed = s.scene.objects[0].type == "bed";
    kinds.insert(bed ? "bed" : "seat");
    if (!bed) {
      // starts facing the object, 0.55-0.85 m beyond its front face; first step gets close
      auto [lo, hi] = Built(s).LocalBounds();
      Eigen::Vector2d local = HumanInObjectFrame(s);
      EXPECT_GE(local.x() - hi.x(), 0.55 - kTol);
      EXPECT_LE(local.x() - hi.x(), 0.85 + kTol);
      EXPECT_LE(
          std::abs(core::WrapAngle(s.scene.humans[0].yaw_rad - s.scene.objects[0].yaw_rad - M_PI)),
          20 * kDegToRad + kTol);
      EXPECT_EQ(s.plan["steps"][0]["pairs"][0]["part"], "none");
      EXPECT_EQ(s.plan["steps"][0]["pairs"][0]["direction"], "front");
    }
    ExpectRunnable(s);
  }
  EXPECT_EQ(kinds.size(), 2u);
}

TEST(SuitesTest, FarSuitesStartOneToSixMetresAwayAndWalkFirst) {
  struct Want {
    std::string suite;
    std::set<std::string> types;
    ExtraCheck extra;
    size_t steps;
  };
  for (const Want& w :
       {Want{"sit-far", {"chair", "armchair", "sofa", "stool", "high_stool"}, ExtraCheck::kNone, 2},
        Want{"lie-far", {"bed"}, ExtraCheck::kLieAlongBed, 3},
        Want{"reach-far", {std::string(kMarkerType)}, ExtraCheck::kHandAtPoint, 2}}) {
    std::set<std::string> types;
    std::set<int> hands;
    for (int i = 0; i < kSamples; ++i) {
      EpisodeSpec s = Make(w.suite, core::DeriveSeed(5, i));
      ASSERT_EQ(s.scene.objects.size(), 1u);
      types.insert(s.scene.objects[0].type);
      hands.insert(static_cast<int>(s.joint));
      EXPECT_EQ(s.extra, w.extra);
      ASSERT_EQ(s.plan["steps"].size(), w.steps) << s.plan.dump();
      EXPECT_EQ(s.plan["steps"][0]["pairs"][0]["part"], "none");
      EXPECT_EQ(s.plan["steps"][0]["pairs"][0]["direction"], "front");
      // 1-6 m beyond the middle of the front face, within +-60 deg of the front direction
      auto [lo, hi] = Built(s).LocalBounds();
      Eigen::Vector2d local = HumanInObjectFrame(s);
      Eigen::Vector2d from_face(local.x() - hi.x(), local.y() - 0.5 * (lo.y() + hi.y()));
      EXPECT_GE(from_face.norm(), 1.0 - kTol);
      EXPECT_LE(from_face.norm(), 6.0 + kTol);
      EXPECT_LE(std::abs(std::atan2(from_face.y(), from_face.x())), 60 * kDegToRad + kTol);
      core::StatusOr<core::SceneCatalog> catalog = world::BuildCatalog(s.scene);
      ASSERT_TRUE(catalog.ok()) << catalog.status();
      core::StatusOr<plan::ContactChain> chain = plan::ParseContactChainJson(s.plan, "suite");
      ASSERT_TRUE(chain.ok()) << chain.status();
      EXPECT_TRUE(plan::ValidateAndGround(*chain, *catalog).ok());
    }
    EXPECT_EQ(types, w.types) << w.suite;
    if (w.suite == "reach-far") {
      EXPECT_EQ(hands.size(), 2u);
    }
  }
}

// a spec with one object, one standing human and an extra check, and its catalog
struct ExtraCase {
  EpisodeSpec spec;
  core::SceneCatalog catalog;
};

ExtraCase Case(const world::ObjectSpec& object, ExtraCheck extra, core::BodyJoint joint) {
  ExtraCase c;
  c.spec.extra = extra;
  c.spec.object_id = object.id;
  c.spec.joint = joint;
  c.spec.scene.name = "extra_test";
  c.spec.scene.objects = {object};
  c.spec.scene.humans = {world::HumanSpec{}};
  core::StatusOr<core::SceneCatalog> catalog = world::BuildCatalog(c.spec.scene);
  EXPECT_TRUE(catalog.ok()) << catalog.status();
  if (catalog.ok()) c.catalog = *catalog;
  return c;
}

BodyPointArray Points(const Eigen::Vector3d& pelvis, const Eigen::Vector3d& head) {
  BodyPointArray p;
  p.fill(pelvis);
  p[static_cast<int>(core::BodyJoint::kHead)] = head;
  return p;
}

world::ObjectSpec Bed(double yaw_deg) {
  world::ObjectSpec bed;
  bed.id = "bed000";
  bed.type = "bed";
  bed.pos = Eigen::Vector3d(1.0, 2.0, 0);
  bed.yaw_rad = yaw_deg * kDegToRad;
  return bed;
}

TEST(SuitesTest, HandAtPointCheck) {
  world::ObjectSpec marker;
  marker.id = "marker000";
  marker.type = kMarkerType;
  marker.pos = Eigen::Vector3d(0.4, -0.3, 1.0);
  ExtraCase c = Case(marker, ExtraCheck::kHandAtPoint, core::BodyJoint::kRightHand);
  for (double offset : {0.0, 0.04, 0.06, 0.3}) {
    BodyPointArray p = Points(Eigen::Vector3d(0, 0, 0.96), Eigen::Vector3d(0, 0, 1.6));
    p[static_cast<int>(core::BodyJoint::kRightHand)] = marker.pos + Eigen::Vector3d(0, offset, 0);
    p[static_cast<int>(core::BodyJoint::kLeftHand)] = marker.pos;  // the other hand does not count
    ExtraResult r = EvaluateExtra(c.spec, c.catalog, p);
    EXPECT_EQ(r.metric, "hand_distance_m");
    EXPECT_NEAR(r.value, offset, kTol);
    EXPECT_EQ(r.pass, offset <= kReachTolM) << offset;
  }
  // no extra check: always passes
  c.spec.extra = ExtraCheck::kNone;
  ExtraResult none =
      EvaluateExtra(c.spec, c.catalog, Points(Eigen::Vector3d::Zero(), Eigen::Vector3d::UnitZ()));
  EXPECT_TRUE(none.pass);
  EXPECT_TRUE(none.metric.empty());
}

TEST(SuitesTest, LieAlongBedCheck) {
  // a bed at yaw -90 degrees has its pillow end (local +y) towards world +x
  ExtraCase c = Case(Bed(-90), ExtraCheck::kLieAlongBed, core::BodyJoint::kPelvis);
  const Eigen::Vector3d pelvis(1.0, 2.0, 0.6);
  struct Pose {
    double head_yaw_deg;
    bool pass;
  };
  for (Pose pose : {Pose{0, true}, Pose{25, true}, Pose{-29, true}, Pose{35, false},
                    Pose{90, false}, Pose{180, false}}) {
    double a = pose.head_yaw_deg * kDegToRad;
    Eigen::Vector3d head = pelvis + 0.6 * Eigen::Vector3d(std::cos(a), std::sin(a), 0.1);
    ExtraResult r = EvaluateExtra(c.spec, c.catalog, Points(pelvis, head));
    EXPECT_EQ(r.metric, "lie_axis_error_deg");
    EXPECT_NEAR(r.value, std::abs(pose.head_yaw_deg), 1e-6);
    EXPECT_EQ(r.pass, pose.pass) << pose.head_yaw_deg;
  }
  // upright (sitting on the edge): no lying direction, fails whatever the direction
  ExtraResult upright =
      EvaluateExtra(c.spec, c.catalog, Points(pelvis, pelvis + Eigen::Vector3d(0.1, 0, 0.6)));
  EXPECT_NEAR(upright.value, 0.0, 1e-6);
  EXPECT_FALSE(upright.pass);
  // a missing object fails
  c.spec.object_id = "bed999";
  ExtraResult missing = EvaluateExtra(c.spec, c.catalog, Points(pelvis, pelvis));
  EXPECT_FALSE(missing.pass);
  EXPECT_TRUE(std::isnan(missing.value));
}

// the check's conventions against the simulated humanoid: tipped over backwards so its head
// points the way it faced, it lies along a bed whose pillow end is in front of it
TEST(SuitesTest, LieAlongBedCheckOnSimulatedBody) {
  ExtraCase c = Case(Bed(-90), ExtraCheck::kLieAlongBed, core::BodyJoint::kPelvis);
  c.spec.scene.objects[0].pos = Eigen::Vector3d(0, 3.0, 0);  // out of the human's way
  core::StatusOr<core::SceneCatalog> catalog = world::BuildCatalog(c.spec.scene);
  ASSERT_TRUE(catalog.ok());
  core::StatusOr<std::unique_ptr<world::SimWorld>> w = BuildWorld(c.spec.scene, *catalog);
  ASSERT_TRUE(w.ok()) << w.status();
  const mjModel* m = (*w)->model();
  mjData* d = (*w)->data();
  mj_kinematics(m, d);
  EXPECT_FALSE(EvaluateExtra(c.spec, *catalog, (*w)->BodyPoints(d, 0)).pass);  // standing
  int root = (*w)->agent(0).root_qpos;
  Eigen::Quaterniond q(Eigen::AngleAxisd(M_PI / 2, Eigen::Vector3d::UnitY()));
  d->qpos[root + 2] = 0.6;
  d->qpos[root + 3] = q.w();
  d->qpos[root + 4] = q.x();
  d->qpos[root + 5] = q.y();
  d->qpos[root + 6] = q.z();
  mj_kinematics(m, d);
  ExtraResult lying = EvaluateExtra(c.spec, *catalog, (*w)->BodyPoints(d, 0));
  EXPECT_LT(lying.value, 5.0);
  EXPECT_TRUE(lying.pass);
}

}  // namespace
}  // namespace simhuman::eval
