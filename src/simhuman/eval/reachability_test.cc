#include "simhuman/eval/reachability.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "simhuman/plan/validate.h"

namespace simhuman::eval {
namespace {

using ::testing::HasSubstr;

// a bed whose front (long side, +x local) faces world +x with its front face at x = front_m,
// and one human at the origin of scale `scale`
struct Setup {
  world::SceneSpec spec;
  core::SceneCatalog catalog;
};

Setup BedScene(double bed_x, double human_scale = 1.0) {
  Setup s;
  world::ObjectSpec bed;
  bed.id = "bed000";
  bed.type = "bed";
  bed.pos = Eigen::Vector3d(bed_x, 0, 0);
  bed.yaw_rad = M_PI;  // front (+x local) towards the human at the origin
  s.spec.objects = {bed};
  world::HumanSpec h;
  h.scale = human_scale;
  s.spec.humans = {h};
  core::StatusOr<core::SceneCatalog> c = world::BuildCatalog(s.spec);
  EXPECT_TRUE(c.ok()) << c.status();
  if (c.ok()) s.catalog = *c;
  return s;
}

// the front face of the default bed (width 1.5) is 0.75 m from its origin
constexpr double kHalfWidth = 0.75;

absl::Status Check(const Setup& s, const std::string& plan_json) {
  core::StatusOr<plan::ContactChain> chain =
      plan::ParseAndGround(plan_json, "plan.json", s.catalog);
  EXPECT_TRUE(chain.ok()) << chain.status();
  if (!chain.ok()) return chain.status();
  return CheckWithinReach(*chain, s.catalog, s.spec.humans);
}

const char kLie[] = R"([
  [["bed000", "mattress", "pelvis", "contact", "up"], ["bed000", "pillow", "head", "not contact", "up"]],
  [["bed000", "mattress", "pelvis", "contact", "up"], ["bed000", "pillow", "head", "contact", "up"]]
])";

TEST(ReachabilityTest, NearObjectPasses) {
  // mattress 0.4 m away; the pillow of step 2 is farther, but the bed was reached in step 1
  EXPECT_TRUE(Check(BedScene(0.4 + kHalfWidth), kLie).ok());
}

TEST(ReachabilityTest, FarObjectNamesObjectDistanceAndStep) {
  absl::Status st = Check(BedScene(3.2 + kHalfWidth), kLie);
  ASSERT_FALSE(st.ok());
  EXPECT_EQ(st.code(), absl::StatusCode::kInvalidArgument);
  EXPECT_THAT(st.message(), HasSubstr("plan.json: step 1 (/0): object 'bed000' (part 'mattress') "
                                      "is 3.2 m from where human 0 starts, beyond the 1.0 m a "
                                      "human reaches without walking; add a get-close step for "
                                      "'bed000' before step 1"));
}

TEST(ReachabilityTest, LaterFirstContactIsReportedWithItsStep) {
  const char plan[] = R"({"steps": [
    {"pairs": [{"object": "bed000", "part": "mattress", "joint": "pelvis",
                "contact": "not contact", "direction": "up"}]},
    {"pairs": [{"object": "bed000", "part": "mattress", "joint": "pelvis",
                "contact": "contact", "direction": "up"}]}]})";
  absl::Status st = Check(BedScene(2.0 + kHalfWidth), plan);
  ASSERT_FALSE(st.ok());
  EXPECT_THAT(st.message(), HasSubstr("step 2 (/steps/1)"));
  EXPECT_THAT(st.message(), HasSubstr("is 2.0 m from where step 1 leaves human 0"));
}

TEST(ReachabilityTest, GetCloseStepBeforeAllowsFarObjects) {
  const char plan[] = R"([
    [["bed000", "none", "none", "none", "front"]],
    [["bed000", "mattress", "pelvis", "contact", "up"]]
  ])";
  EXPECT_TRUE(Check(BedScene(3.2 + kHalfWidth), plan).ok());
}

TEST(ReachabilityTest, NotContactAndNotCarePairsAreNotChecked) {
  const char plan[] = R"([
    [["bed000", "mattress", "pelvis", "not contact", "up"],
     ["bed000", "pillow", "head", "not care", "none"]]
  ])";
  EXPECT_TRUE(Check(BedScene(3.2 + kHalfWidth), plan).ok());
}

TEST(ReachabilityTest, OneNearPairOfAStepIsEnough) {
  // the pillow is 0.05 m from the bed's long edge on the far side of the mattress, but the
  // mattress in the same step is near
  const char plan[] = R"([
    [["bed000", "pillow", "head", "contact", "up"], ["bed000", "mattress", "pelvis", "contact", "up"]]
  ])";
  EXPECT_TRUE(Check(BedScene(0.9 + kHalfWidth), plan).ok());
  const char pillow_only[] = R"([[["bed000", "pillow", "head", "contact", "up"]]])";
  absl::Status st = Check(BedScene(0.9 + kHalfWidth), pillow_only);
  ASSERT_FALSE(st.ok());
  EXPECT_THAT(st.message(), HasSubstr("(part 'pillow')"));
}

TEST(ReachabilityTest, LimitScalesWithTheHuman) {
  EXPECT_TRUE(Check(BedScene(0.9 + kHalfWidth), kLie).ok());
  absl::Status child = Check(BedScene(0.9 + kHalfWidth, 0.7), kLie);
  ASSERT_FALSE(child.ok());
  EXPECT_THAT(child.message(), HasSubstr("beyond the 0.7 m a human reaches"));
}

// the living room's desk as UniHSI's Table 7 has it: a chair at (0, 0) facing +x, a table at
// (1, 0) with a laptop at its near edge, a bed at (0, -3.5) facing +x; the human 3 m away
Setup DeskScene() {
  Setup s;
  auto add = [&](const char* id, const char* type, double x, double y, double yaw, double z) {
    world::ObjectSpec o;
    o.id = id;
    o.type = type;
    o.pos = Eigen::Vector3d(x, y, z);
    o.yaw_rad = yaw;
    s.spec.objects.push_back(o);
  };
  add("chair000", "chair", 0, 0, 0, 0);
  add("table001", "table", 1.0, 0, M_PI, 0);
  add("laptop002", "laptop", 0.8, 0, M_PI, 0.75);
  add("bed003", "bed", 0, -3.5, 0, 0);
  world::HumanSpec h;
  h.pos_xy = Eigen::Vector2d(3.0, 0);
  s.spec.humans = {h};
  core::StatusOr<core::SceneCatalog> c = world::BuildCatalog(s.spec);
  EXPECT_TRUE(c.ok()) << c.status();
  if (c.ok()) s.catalog = *c;
  return s;
}

TEST(ReachabilityTest, FollowsWhereEarlierStepsLeaveTheHuman) {
  // Table 7: walk to the chair, sit, both hands on the laptop: within reach of the seat
  const char desk[] = R"([
    [["chair000", "none", "none", "none", "front"]],
    [["chair000", "seat surface", "pelvis", "contact", "up"]],
    [["chair000", "seat surface", "pelvis", "contact", "up"],
     ["laptop002", "keyboard", "left hand", "contact", "none"],
     ["laptop002", "keyboard", "right hand", "contact", "none"]]
  ])";
  EXPECT_TRUE(Check(DeskScene(), desk).ok());
  // the bed's pillow from that seat is out of reach, though the human started nowhere near it
  const char pillow[] = R"([
    [["chair000", "none", "none", "none", "front"]],
    [["chair000", "seat surface", "pelvis", "contact", "up"]],
    [["bed003", "pillow", "right hand", "contact", "up"]]
  ])";
  absl::Status st = Check(DeskScene(), pillow);
  ASSERT_FALSE(st.ok());
  EXPECT_THAT(st.message(), HasSubstr("step 3 (/2): object 'bed003' (part 'pillow') is"));
  EXPECT_THAT(st.message(), HasSubstr("m from where step 2 leaves human 0"));
  // walking to the bed leaves the laptop behind
  const char back[] = R"([
    [["bed003", "none", "none", "none", "front"]],
    [["laptop002", "keyboard", "right hand", "contact", "up"]]
  ])";
  st = Check(DeskScene(), back);
  ASSERT_FALSE(st.ok());
  EXPECT_THAT(st.message(), HasSubstr("from where step 1 leaves human 0"));
}

TEST(ReachabilityTest, UniHsiTableFilesAreSceneAndPlanAndPassThePreflight) {
  // UniHSI's Tables 5-7, each one file given as both --scene and --plan
  for (const char* name :
       {"unihsi_table5_plan.json", "unihsi_table6_plan.json", "unihsi_table7_plan.json"}) {
    const std::string path = std::string(SIMHUMAN_SOURCE_DIR) + "/assets/scenes/" + name;
    core::StatusOr<world::SceneSpec> scene = world::LoadScene(path);
    ASSERT_TRUE(scene.ok()) << scene.status();
    core::StatusOr<core::SceneCatalog> catalog = world::BuildCatalog(*scene);
    ASSERT_TRUE(catalog.ok()) << catalog.status();
    core::StatusOr<plan::ContactChain> chain = plan::LoadContactChainFile(path);
    ASSERT_TRUE(chain.ok()) << chain.status();
    ASSERT_TRUE(plan::ValidateAndGround(*chain, *catalog).ok()) << name;
    EXPECT_TRUE(CheckWithinReach(*chain, *catalog, scene->humans).ok()) << name;
  }
}

}  // namespace
}  // namespace simhuman::eval
