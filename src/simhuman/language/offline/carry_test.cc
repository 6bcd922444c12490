// The offline planner's carry commands against the built-in carry scenes.

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <string>

#include "simhuman/language/offline_planner.h"
#include "simhuman/world/scene.h"

namespace simhuman::language {
namespace {

using ::testing::HasSubstr;
using ::testing::StartsWith;

struct Planned {
  absl::Status status;
  std::string summary;  // carry summaries and pair counts, steps joined by " / "
  plan::ContactChain chain;
};

Planned PlanIn(const std::string& scene_name, const std::string& command) {
  world::SceneSpec spec = *world::LoadScene(scene_name);
  core::SceneCatalog catalog = *world::BuildCatalog(spec);
  PlanContext context;
  context.scene = &catalog;
  for (const world::HumanSpec& h : spec.humans) {
    context.agents.push_back({h.pos_xy.x(), h.pos_xy.y(), h.yaw_rad, h.posture});
  }
  OfflinePlanner planner;
  core::StatusOr<PlanResult> r = planner.Plan(command, context);
  Planned out;
  out.status = r.status();
  if (!r.ok()) return out;
  out.chain = r->chain;
  for (const plan::ContactStep& s : r->chain.steps) {
    if (!out.summary.empty()) out.summary += " / ";
    out.summary += s.carry ? plan::CarrySummary(*s.carry)
                           : s.pairs.front().object + " x" + std::to_string(s.pairs.size());
  }
  return out;
}

TEST(OfflineCarryTest, CarriesToObjectsAndHolds) {
  Planned p = PlanIn("carry_demo", "carry the box to the bed");
  ASSERT_TRUE(p.status.ok()) << p.status;
  EXPECT_EQ(p.summary, "carry box000 by 0 to beside bed001");
  // grounded: two hand pairs and a goal clear of the bed
  ASSERT_EQ(p.chain.steps[0].pairs.size(), 2u);
  EXPECT_TRUE(p.chain.steps[0].carry->goal.has_value());
  for (const char* c : {"bring the box over to the bed", "take the box to the bed",
                        "please carry the orange box to the bed"}) {
    EXPECT_EQ(PlanIn("carry_demo", c).summary, "carry box000 by 0 to beside bed001") << c;
  }
  EXPECT_EQ(PlanIn("carry_demo", "move the armchair next to the sofa").summary,
            "carry armchair003 by 0 to beside sofa002");
  EXPECT_EQ(PlanIn("carry_demo", "pick up the box").summary, "carry box000 by 0 and hold");
  EXPECT_EQ(PlanIn("carry_demo", "pick up the box, then put it down here").summary,
            "carry box000 by 0 and hold / carry box000 by 0 to here");
  EXPECT_EQ(PlanIn("carry_demo", "pick up the box and carry it to the sofa").summary,
            "carry box000 by 0 and hold / carry box000 by 0 to beside sofa002");
}

TEST(OfflineCarryTest, TeamsCarryTogether) {
  EXPECT_EQ(PlanIn("carry_team_demo", "you two carry the long box to the bed").summary,
            "carry long_box000 by 0,1 to beside bed002");
  // the long box needs two: they are assigned without being asked
  EXPECT_EQ(PlanIn("carry_team_demo", "carry the long box to the bed").summary,
            "carry long_box000 by 0,1 to beside bed002");
  EXPECT_EQ(PlanIn("carry_team_demo", "both of you lift the sofa").summary,
            "carry sofa001 by 0,1 and hold");
  Planned p = PlanIn("carry_team_demo", "the two of you carry the sofa to the bed");
  ASSERT_TRUE(p.status.ok()) << p.status;
  ASSERT_EQ(p.chain.steps[0].pairs.size(), 4u);
  EXPECT_EQ(p.chain.steps[0].pairs[2].agent, 1);
}

TEST(OfflineCarryTest, RefusesClearly) {
  Planned door = PlanIn("carry_team_demo", "you two carry the long box to the door");
  EXPECT_TRUE(absl::IsInvalidArgument(door.status)) << door.status;
  EXPECT_THAT(std::string(door.status.message()), HasSubstr("this scene has no door"));
  Planned three = PlanIn("carry_team_demo", "you three carry the long box to the bed");
  EXPECT_THAT(std::string(three.status.message()), HasSubstr("valid agents are 0..1"));
  Planned alone = PlanIn("carry_demo", "carry the sofa to the bed");
  EXPECT_TRUE(absl::IsInvalidArgument(alone.status));
  EXPECT_THAT(std::string(alone.status.message()), HasSubstr("static furniture"));
  Planned heavy = PlanIn("carry_team_demo", "lift the long box and carry it to the bed");
  EXPECT_TRUE(heavy.status.ok()) << heavy.status;  // two are assigned
  Planned nothing = PlanIn("carry_demo", "put it down here");
  EXPECT_TRUE(absl::IsInvalidArgument(nothing.status));
  Planned not_held = PlanIn("carry_demo", "carry the box to the bed, then put it down here");
  EXPECT_THAT(std::string(not_held.status.message()), HasSubstr("is not being held"));
  Planned onto = PlanIn("carry_demo", "carry the box onto the bed");
  EXPECT_THAT(std::string(onto.status.message()), HasSubstr("on the floor"));
}

TEST(OfflineCarryTest, SmallBoxesAreStillGraspedAndAmbiguityAsks) {
  // tabletop boxes are not carried: "pick up" stays a reach
  Planned reach = PlanIn("tabletop_demo", "pick up the red box");
  ASSERT_TRUE(reach.status.ok()) << reach.status;
  EXPECT_FALSE(reach.chain.steps[0].carry.has_value());
  // a floor box put on the bed stays a grasp-and-place
  Planned put = PlanIn("bedroom", "put the box on the bed");
  ASSERT_TRUE(put.status.ok()) << put.status;
  for (const plan::ContactStep& s : put.chain.steps) EXPECT_FALSE(s.carry.has_value());
  Planned which =
      PlanIn(std::string(SIMHUMAN_SOURCE_DIR) + "/tests/data/language/two_carry_boxes.json",
             "carry the box to the bed");
  EXPECT_TRUE(absl::IsFailedPrecondition(which.status)) << which.status;
  EXPECT_THAT(std::string(which.status.message()), StartsWith("Which box"));
}

}  // namespace
}  // namespace simhuman::language
