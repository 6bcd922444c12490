#include "simhuman/plan/validate.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "simhuman/plan/test_scene.h"

namespace simhuman::plan {
namespace {

using fixtures::MakeTestScene;
using fixtures::PlanDataPath;
using ::testing::HasSubstr;

std::string GroundError(const std::string& name, const core::SceneCatalog& scene) {
  absl::StatusOr<ContactChain> chain = LoadAndGroundFile(PlanDataPath(name), scene);
  EXPECT_FALSE(chain.ok()) << name << " grounded but should not";
  if (chain.ok()) return {};
  EXPECT_EQ(chain.status().code(), absl::StatusCode::kInvalidArgument) << chain.status();
  EXPECT_THAT(std::string(chain.status().message()), HasSubstr(name));
  return std::string(chain.status().message());
}

TEST(PlanValidateTest, GroundsSimhumanForm) {
  core::SceneCatalog scene = MakeTestScene();
  scene.agents.resize(2);
  absl::StatusOr<ContactChain> chain =
      LoadAndGroundFile(PlanDataPath("chain_simhuman.json"), scene);
  ASSERT_TRUE(chain.ok()) << chain.status();
  EXPECT_EQ(chain->steps[1].pairs[0].part, "seat surface");  // alias "seat" grounded
  EXPECT_FALSE(chain->steps[1].pairs[0].part_joint.has_value());
  const ContactPair& foot_on_knee = chain->steps[2].pairs[1];
  EXPECT_EQ(foot_on_knee.part, "left knee");
  EXPECT_EQ(foot_on_knee.part_joint, core::BodyJoint::kLeftKnee);
  EXPECT_EQ(foot_on_knee.joint, core::BodyJoint::kRightFoot);
  EXPECT_TRUE(chain->steps[0].pairs[0].IsGetClose());
}

// an agent whose body has one extra point, as world/ exports a hand's palm
core::SceneCatalog SceneWithPalm() {
  core::SceneCatalog scene = MakeTestScene();
  scene.agents.resize(2);
  scene.agents[1].kind = "humanoid_right_hand";
  scene.agents[1].body_points.points.push_back({"right palm", {"right_palm_centre"}});
  return scene;
}

std::string PalmPlan(int agent) {
  return R"({"steps": [{"pairs": [{"object": "chair000", "part": "seat", "joint": "Right_Palm",
             "contact": "contact", "direction": "up", "agent": )" +
         std::to_string(agent) + "}]}]}";
}

TEST(PlanValidateTest, JointNamesGroundAgainstTheAgentsBodyPoints) {
  const core::SceneCatalog scene = SceneWithPalm();
  // parsing accepts any joint name; grounding finds it in the agent's catalog
  absl::StatusOr<ContactChain> parsed = ParseContactChain(PalmPlan(1), "<palm>");
  ASSERT_TRUE(parsed.ok()) << parsed.status();
  EXPECT_FALSE(parsed->steps[0].pairs[0].joint.has_value());
  absl::StatusOr<ContactChain> chain = ParseAndGround(PalmPlan(1), "<palm>", scene);
  ASSERT_TRUE(chain.ok()) << chain.status();
  const ContactPair& pair = chain->steps[0].pairs[0];
  EXPECT_EQ(pair.joint, static_cast<core::BodyJoint>(core::kNumBodyJoints));
  EXPECT_EQ(pair.joint_name, "right palm");
  EXPECT_EQ(ContactChainToJson(*chain)["steps"][0]["pairs"][0]["joint"], "right palm");
  // an alias of the point grounds too
  std::string alias = PalmPlan(1);
  alias.replace(alias.find("Right_Palm"), 10, "right palm centre");
  ASSERT_TRUE(ParseAndGround(alias, "<alias>", scene).ok());
  // human 0 has no palm: the error names the pointer, the human and its body points
  absl::StatusOr<ContactChain> bad = ParseAndGround(PalmPlan(0), "<palm>", scene);
  ASSERT_FALSE(bad.ok());
  EXPECT_THAT(std::string(bad.status().message()),
              HasSubstr("/steps/0/pairs/0/joint: unknown joint 'right palm' for human 0; valid "
                        "joints: pelvis, torso"));
  // standard joints still ground for every agent
  ASSERT_TRUE(LoadAndGroundFile(PlanDataPath("chain_simhuman.json"), scene).ok());
}

TEST(PlanValidateTest, GroundsScenePlanNamesWithDigitsAndAliases) {
  core::SceneCatalog scene = MakeTestScene();
  absl::StatusOr<ContactChain> chain =
      LoadAndGroundFile(PlanDataPath("sceneplan_medium.json"), scene);
  ASSERT_TRUE(chain.ok()) << chain.status();
  EXPECT_EQ(chain->steps[1].pairs[0].part, "seat surface");  // "seat soft surface42"
  EXPECT_EQ(chain->steps[2].pairs[1].part, "back surface");  // "back soft surface47"
  EXPECT_EQ(chain->steps[3].pairs[1].part, "left arm");      // exact alias "arm sofa style44"
  EXPECT_EQ(chain->steps[3].pairs[2].part, "right arm");     // exact alias "arm sofa style48"
  EXPECT_EQ(chain->steps[5].pairs[1].part_joint, core::BodyJoint::kLeftKnee);

  absl::StatusOr<ContactChain> bed = LoadAndGroundFile(PlanDataPath("chain_tuple.json"), scene);
  ASSERT_TRUE(bed.ok()) << bed.status();
  EXPECT_EQ(bed->steps[1].pairs[0].part, "mattress");  // "mattress25"
  EXPECT_EQ(bed->steps[2].pairs[3].part, "pillow");    // "pillow17"
}

TEST(PlanValidateTest, GroundingIsIdempotentAndSurvivesRoundTrip) {
  core::SceneCatalog scene = MakeTestScene();
  absl::StatusOr<ContactChain> a = LoadAndGroundFile(PlanDataPath("sceneplan_medium.json"), scene);
  ASSERT_TRUE(a.ok()) << a.status();
  ContactChain again = *a;
  ASSERT_TRUE(ValidateAndGround(again, scene).ok());
  EXPECT_EQ(ContactChainToJson(again), ContactChainToJson(*a));
  absl::StatusOr<ContactChain> b =
      ParseAndGround(ContactChainToJson(*a).dump(), "<roundtrip>", scene);
  ASSERT_TRUE(b.ok()) << b.status();
  EXPECT_EQ(ContactChainToJson(*b), ContactChainToJson(*a));
  EXPECT_EQ(b->steps[5].pairs[1].part_joint, core::BodyJoint::kLeftKnee);
}

TEST(PlanValidateTest, MalformedUnknownObjectListsObjects) {
  std::string msg = GroundError("malformed_unknown_object.json", MakeTestScene());
  EXPECT_THAT(msg, HasSubstr("/steps/1/pairs/0/object: unknown object 'chiar000'; valid "
                             "objects: chair000, bed001"));
}

TEST(PlanValidateTest, MalformedUnknownPartListsParts) {
  std::string msg = GroundError("malformed_unknown_part.json", MakeTestScene());
  EXPECT_THAT(msg, HasSubstr("/steps/1/pairs/0/part: unknown part 'seet' of chair000 (chair); "
                             "valid parts: seat surface, back surface, left arm, right arm"));
  EXPECT_THAT(msg, HasSubstr("body joint"));
}

TEST(PlanValidateTest, MalformedAmbiguousPart) {
  std::string msg = GroundError("malformed_ambiguous_part.json", MakeTestScene());
  EXPECT_THAT(msg, HasSubstr("/0/1/1: ambiguous part 'armrest' of chair000 (chair): it matches "
                             "left arm, right arm"));
}

TEST(PlanValidateTest, AmbiguousAfterDroppingDigits) {
  // "arm sofa style" matches no name exactly, and both arms once digits are dropped; a joint
  // without a side does not pick one
  absl::StatusOr<ContactChain> chain =
      ParseAndGround(R"([[["chair000", "arm sofa style", "torso", "contact", "up"]]])", "<string>",
                     MakeTestScene());
  ASSERT_FALSE(chain.ok());
  EXPECT_THAT(std::string(chain.status().message()), HasSubstr("ambiguous part"));
}

TEST(PlanValidateTest, ASidedJointPicksTheArmOnItsSide) {
  // UniHSI's Table 6 writes "arm sofa style44"/"48" for the two arms; the hand names the side
  absl::StatusOr<ContactChain> chain = ParseAndGround(
      R"([[["chair000", "arm sofa style", "right hand", "contact", "up"],
           ["chair000", "armrest", "left elbow", "contact", "up"]]])",
      "<string>", MakeTestScene());
  ASSERT_TRUE(chain.ok()) << chain.status();
  EXPECT_EQ(chain->steps[0].pairs[0].part, "right arm");
  EXPECT_EQ(chain->steps[0].pairs[1].part, "left arm");
}

TEST(PlanValidateTest, MalformedAgentOutOfRange) {
  std::string msg = GroundError("malformed_agent_out_of_range.json", MakeTestScene());
  EXPECT_THAT(msg, HasSubstr("/steps/0/pairs/0/agent: agent index 2 out of range; the scene has "
                             "1 agent(s), valid indices are 0..0"));
}

TEST(PlanValidateTest, ParseErrorsPassThrough) {
  std::string msg = GroundError("malformed_unknown_joint.json", MakeTestScene());
  EXPECT_THAT(msg, HasSubstr("unknown joint 'butt'"));
}

TEST(PlanValidateTest, ChainsBuiltInCode) {
  core::SceneCatalog scene = MakeTestScene();
  ContactChain chain;
  absl::Status s = ValidateAndGround(chain, scene);
  EXPECT_THAT(std::string(s.message()), HasSubstr("/steps: plan has no steps"));

  chain.steps.emplace_back();
  s = ValidateAndGround(chain, scene);
  EXPECT_THAT(std::string(s.message()), HasSubstr("/steps/0/pairs: step has no pairs"));

  ContactPair pair;
  pair.object = "bed001";
  pair.part = "Pillow";
  pair.joint = core::BodyJoint::kHead;
  pair.type = ContactType::kContact;
  pair.direction = Direction::kUp;
  chain.steps[0].pairs.push_back(pair);
  ASSERT_TRUE(ValidateAndGround(chain, scene).ok());
  EXPECT_EQ(chain.steps[0].pairs[0].part, "pillow");

  // errors leave the chain untouched
  chain.steps[0].pairs[0].part = "Pillow";
  chain.steps[0].pairs.push_back(pair);
  chain.steps[0].pairs[1].object = "sofa";
  s = ValidateAndGround(chain, scene);
  EXPECT_THAT(std::string(s.message()), HasSubstr("/steps/0/pairs/1/object: unknown object"));
  EXPECT_EQ(chain.steps[0].pairs[0].part, "Pillow");
}

TEST(PlanValidateTest, EmptySceneSaysSo) {
  core::SceneCatalog scene;
  absl::StatusOr<ContactChain> chain =
      ParseAndGround(R"([[["chair000", "none", "none", "none", "front"]]])", "<string>", scene);
  ASSERT_FALSE(chain.ok());
  EXPECT_THAT(std::string(chain.status().message()),
              HasSubstr("<string>: /0/0/0: unknown object 'chair000'; the scene has no objects"));
}

}  // namespace
}  // namespace simhuman::plan
