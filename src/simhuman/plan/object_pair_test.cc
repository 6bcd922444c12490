// Object-object pairs (tabletop goals): JSON both ways, grounding errors, metrics.

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "simhuman/plan/contact_chain.h"
#include "simhuman/plan/metrics.h"
#include "simhuman/plan/test_scene.h"
#include "simhuman/plan/validate.h"

namespace simhuman::plan {
namespace {

using ::testing::HasSubstr;

constexpr double kTol = 1e-9;

// a 0.1 m cube with parts "top" (upper slab) and "body" (all of it), origin under its centre
core::CatalogObject Cube(const std::string& id, const Eigen::Vector3d& pos, bool movable) {
  core::CatalogObject o;
  o.id = id;
  o.type = "box";
  o.movable = movable;
  o.pose = core::Pose::FromYaw(pos, 0.0);
  core::Shape top = fixtures::Box({0, 0, 0.09}, {0.05, 0.05, 0.01});
  core::Shape rest = fixtures::Box({0, 0, 0.04}, {0.05, 0.05, 0.04});
  o.parts.push_back(fixtures::Part("top", {"lid"}, top));
  core::CatalogPart body;
  body.name = "body";
  body.aliases = {"whole"};
  body.shapes = {top, rest};
  o.parts.push_back(body);
  o.shapes = {top, rest};
  return o;
}

core::SceneCatalog Scene() {
  core::SceneCatalog s;
  s.objects.push_back(Cube("box000", {0, 0, 0}, true));
  s.objects.push_back(Cube("box001", {1, 0, 0}, true));
  s.objects.push_back(Cube("block002", {2, 0, 0}, false));
  return s;
}

const char kPlan[] = R"({"steps": [
  {"pairs": [{"object": "box000", "part": "body", "joint": "right hand",
              "contact": "contact", "direction": "none"}]},
  {"label": "box000 on box001",
   "pairs": [{"subject_object": "box000", "subject_part": "whole", "object": "box001",
              "part": "lid", "contact": "contact", "direction": "up"}]}]})";

TEST(PlanObjectPairTest, ParsesGroundsAndRoundTrips) {
  core::StatusOr<ContactChain> chain = ParseAndGround(kPlan, "plan.json", Scene());
  ASSERT_TRUE(chain.ok()) << chain.status();
  const ContactPair& p = chain->steps[1].pairs[0];
  EXPECT_TRUE(p.IsObjectPair());
  EXPECT_FALSE(p.IsGetClose());
  EXPECT_FALSE(p.joint.has_value());
  EXPECT_EQ(*p.subject_object, "box000");
  EXPECT_EQ(p.subject_part, "body");  // grounded from the alias "whole"
  EXPECT_EQ(p.part, "top");           // from "lid"
  nlohmann::json j = ContactChainToJson(*chain);
  const nlohmann::json& jp = j["steps"][1]["pairs"][0];
  EXPECT_FALSE(jp.contains("joint"));
  EXPECT_EQ(jp["subject_object"], "box000");
  EXPECT_EQ(jp["subject_part"], "body");
  core::StatusOr<ContactChain> again = ParseAndGround(j.dump(), "again", Scene());
  ASSERT_TRUE(again.ok()) << again.status();
  EXPECT_EQ(ContactChainToJson(*again), j);
}

std::string Error(const std::string& pair) {
  std::string text = R"({"steps": [{"pairs": [)" + pair + "]}]}";
  core::StatusOr<ContactChain> chain = ParseAndGround(text, "plan.json", Scene());
  EXPECT_FALSE(chain.ok());
  return std::string(chain.status().message());
}

TEST(PlanObjectPairTest, MalformedObjectPairsNameThePointer) {
  EXPECT_THAT(Error(R"({"subject_object": "box000", "subject_part": "body", "joint": "pelvis",
                        "object": "box001", "part": "top", "contact": "contact",
                        "direction": "up"})"),
              HasSubstr("/steps/0/pairs/0/joint: an object-object pair"));
  EXPECT_THAT(Error(R"({"subject_object": "box000", "object": "box001", "part": "top",
                        "contact": "contact", "direction": "up"})"),
              HasSubstr("needs 'subject_part'"));
  EXPECT_THAT(Error(R"({"subject_object": "box009", "subject_part": "body", "object": "box001",
                        "part": "top", "contact": "contact", "direction": "up"})"),
              AllOf(HasSubstr("/steps/0/pairs/0/subject_object: unknown object 'box009'"),
                    HasSubstr("movable objects: box000, box001")));
  EXPECT_THAT(Error(R"({"subject_object": "block002", "subject_part": "body",
                        "object": "box001", "part": "top", "contact": "contact",
                        "direction": "up"})"),
              HasSubstr("block002 (box) is not movable"));
  EXPECT_THAT(Error(R"({"subject_object": "box000", "subject_part": "handle",
                        "object": "box001", "part": "top", "contact": "contact",
                        "direction": "up"})"),
              AllOf(HasSubstr("/steps/0/pairs/0/subject_part: unknown part 'handle'"),
                    HasSubstr("valid parts: top, body")));
  EXPECT_THAT(Error(R"({"subject_object": "box000", "subject_part": "body",
                        "object": "box001", "part": "left knee", "contact": "contact",
                        "direction": "up"})"),
              HasSubstr("/steps/0/pairs/0/part: unknown part 'left knee'"));
  EXPECT_THAT(Error(R"({"subject_object": "box000", "subject_part": "body",
                        "object": "box000", "part": "top", "contact": "contact",
                        "direction": "up"})"),
              HasSubstr("cannot be placed on itself"));
  EXPECT_THAT(Error(R"({"subject_object": "box000", "subject_part": "body",
                        "object": "box001", "part": "none", "contact": "contact",
                        "direction": "up"})"),
              HasSubstr("/steps/0/pairs/0/part"));
}

TEST(PlanObjectPairTest, StackedCubeSatisfiesOnTop) {
  core::SceneCatalog scene = Scene();
  core::StatusOr<ContactChain> chain = ParseAndGround(kPlan, "plan.json", scene);
  ASSERT_TRUE(chain.ok());
  const ContactPair& pair = chain->steps[1].pairs[0];
  PairParams params;
  // apart on the floor: 0.9 m between the faces, beside (not above) the top
  PairEval apart = EvaluateObjectPair(pair, scene, params);
  EXPECT_NEAR(apart.distance_m, 0.9, 1e-6);
  EXPECT_FALSE(apart.satisfied);
  EXPECT_TRUE(apart.has_error);
  // stacked: box000 resting on box001's top
  scene.objects[0].pose = core::Pose::FromYaw({1, 0, 0.1}, 0.0);
  PairEval on = EvaluateObjectPair(pair, scene, params);
  EXPECT_NEAR(on.distance_m, 0.0, kTol);
  EXPECT_GT(on.direction_dot, params.direction_dot_min);
  EXPECT_TRUE(on.satisfied);
  // EvaluatePair dispatches to it (no body points needed)
  std::vector<BodyPoints> agents(1);
  EXPECT_TRUE(EvaluatePair(pair, scene, agents, params).satisfied);
  // hovering 5 cm above: still within 0.1 m and above
  scene.objects[0].pose = core::Pose::FromYaw({1, 0, 0.15}, 0.0);
  PairEval hover = EvaluateObjectPair(pair, scene, params);
  EXPECT_NEAR(hover.distance_m, 0.05, 1e-6);
  EXPECT_NEAR(hover.direction_dot, 1.0, 1e-6);
  EXPECT_TRUE(hover.satisfied);
  // touching from the side: close, but not above the top
  scene.objects[0].pose = core::Pose::FromYaw({1, 0.1, 0.0}, 0.0);
  PairEval side = EvaluateObjectPair(pair, scene, params);
  EXPECT_LT(side.distance_m, params.contact_threshold_m);
  EXPECT_LT(side.direction_dot, params.direction_dot_min);
  EXPECT_FALSE(side.satisfied);
}

TEST(PlanObjectPairTest, SideRelationUsesTheObjectsFrame) {
  core::SceneCatalog scene = Scene();
  const char* plan = R"({"steps": [{"pairs": [{"subject_object": "box000",
      "subject_part": "body", "object": "box001", "part": "body", "contact": "contact",
      "direction": "left"}]}]})";
  core::StatusOr<ContactChain> chain = ParseAndGround(plan, "p", scene);
  ASSERT_TRUE(chain.ok()) << chain.status();
  // box000 just left (+y) of box001
  scene.objects[0].pose = core::Pose::FromYaw({1, 0.12, 0}, 0.0);
  PairEval left = EvaluateObjectPair(chain->steps[0].pairs[0], scene, PairParams());
  EXPECT_NEAR(left.distance_m, 0.02, 1e-6);
  EXPECT_TRUE(left.satisfied);
  scene.objects[0].pose = core::Pose::FromYaw({1, -0.12, 0}, 0.0);
  EXPECT_FALSE(EvaluateObjectPair(chain->steps[0].pairs[0], scene, PairParams()).satisfied);
}

TEST(PlanObjectPairTest, TupleFormHasNoObjectPairs) {
  // the tuple form keeps its 5 fields; a subject cannot be written there
  core::StatusOr<ContactChain> chain =
      ParseAndGround(R"([[["box001", "top", "box000", "contact", "up"]]])", "t", Scene());
  ASSERT_FALSE(chain.ok());
  EXPECT_NE(chain.status().message().find("/0/0/2: unknown joint 'box000'"), std::string::npos)
      << chain.status();
}

}  // namespace
}  // namespace simhuman::plan
