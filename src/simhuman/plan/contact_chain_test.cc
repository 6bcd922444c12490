#include "simhuman/plan/contact_chain.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "simhuman/plan/test_scene.h"
#include "simhuman/plan/validate.h"

namespace simhuman::plan {
namespace {

using fixtures::PlanDataPath;
using ::testing::HasSubstr;

// parses a file that must fail and returns its message
std::string LoadError(const std::string& name) {
  absl::StatusOr<ContactChain> chain = LoadContactChainFile(PlanDataPath(name));
  EXPECT_FALSE(chain.ok()) << name << " parsed but should not";
  if (chain.ok()) return {};
  EXPECT_EQ(chain.status().code(), absl::StatusCode::kInvalidArgument) << chain.status();
  EXPECT_THAT(std::string(chain.status().message()), HasSubstr(name));
  return std::string(chain.status().message());
}

TEST(PlanEnumsTest, NamesRoundTrip) {
  for (ContactType t : {ContactType::kContact, ContactType::kNotContact, ContactType::kNotCare}) {
    EXPECT_EQ(ParseContactType(ContactTypeName(t)), t);
  }
  for (const std::string& name : DirectionNames()) {
    ASSERT_TRUE(ParseDirection(name).has_value()) << name;
    EXPECT_EQ(DirectionName(*ParseDirection(name)), name);
  }
  EXPECT_EQ(ContactTypeName(ContactType::kNotContact), "not contact");
  EXPECT_EQ(ParseContactType("Not_Contact"), ContactType::kNotContact);
  EXPECT_EQ(ParseContactType("notcontact"), std::nullopt);
  EXPECT_EQ(ParseDirection("UP"), Direction::kUp);
  EXPECT_EQ(ParseDirection("above"), std::nullopt);
  EXPECT_EQ(DirectionNames().size(), 7u);
  EXPECT_TRUE(IsSideDirection(Direction::kLeft));
  EXPECT_FALSE(IsSideDirection(Direction::kUp));
  EXPECT_FALSE(IsSideDirection(Direction::kNone));
}

TEST(PlanParseTest, SimhumanForm) {
  absl::StatusOr<ContactChain> chain = LoadContactChainFile(PlanDataPath("chain_simhuman.json"));
  ASSERT_TRUE(chain.ok()) << chain.status();
  EXPECT_EQ(chain->form, ChainForm::kSimhuman);
  ASSERT_EQ(chain->steps.size(), 4u);

  const ContactStep& s0 = chain->steps[0];
  EXPECT_EQ(s0.label, "get close to the chair");
  ASSERT_EQ(s0.pairs.size(), 1u);
  EXPECT_TRUE(s0.pairs[0].IsGetClose());
  EXPECT_EQ(s0.pairs[0].object, "chair000");
  EXPECT_EQ(s0.pairs[0].part, "none");
  EXPECT_FALSE(s0.pairs[0].joint.has_value());
  EXPECT_EQ(s0.pairs[0].direction, Direction::kFront);
  EXPECT_EQ(s0.pairs[0].where, "/steps/0/pairs/0");

  const ContactPair& sit = chain->steps[1].pairs[0];
  EXPECT_FALSE(sit.IsGetClose());
  EXPECT_EQ(sit.part, "seat");  // grounding to "seat surface" happens in ValidateAndGround
  EXPECT_EQ(sit.joint, core::BodyJoint::kPelvis);
  EXPECT_EQ(sit.type, ContactType::kContact);
  EXPECT_EQ(sit.direction, Direction::kUp);
  EXPECT_EQ(sit.agent, 0);

  const ContactStep& s2 = chain->steps[2];
  ASSERT_EQ(s2.pairs.size(), 4u);
  EXPECT_EQ(s2.pairs[1].part, "left knee");
  EXPECT_EQ(s2.pairs[1].joint, core::BodyJoint::kRightFoot);
  EXPECT_EQ(s2.pairs[1].direction, Direction::kNone);
  EXPECT_EQ(s2.pairs[2].type, ContactType::kNotContact);
  EXPECT_EQ(s2.pairs[3].type, ContactType::kNotCare);

  EXPECT_TRUE(chain->steps[3].label.empty());
  EXPECT_EQ(chain->steps[3].pairs[0].agent, 1);
}

TEST(PlanParseTest, TupleFormBareList) {
  absl::StatusOr<ContactChain> chain = LoadContactChainFile(PlanDataPath("chain_tuple.json"));
  ASSERT_TRUE(chain.ok()) << chain.status();
  EXPECT_EQ(chain->form, ChainForm::kTuple);
  ASSERT_EQ(chain->steps.size(), 3u);
  EXPECT_TRUE(chain->steps[0].pairs[0].IsGetClose());
  EXPECT_EQ(chain->steps[0].pairs[0].direction, Direction::kFront);
  ASSERT_EQ(chain->steps[1].pairs.size(), 2u);
  EXPECT_EQ(chain->steps[1].pairs[1].part, "mattress25");
  EXPECT_EQ(chain->steps[1].pairs[1].joint, core::BodyJoint::kHead);
  EXPECT_EQ(chain->steps[1].pairs[1].type, ContactType::kNotContact);
  EXPECT_EQ(chain->steps[1].pairs[1].where, "/1/1");
  EXPECT_EQ(chain->steps[2].pairs.size(), 4u);
  EXPECT_EQ(FieldPointer(*chain, 1, 1, "part"), "/1/1/1");
  EXPECT_EQ(FieldPointer(*chain, 1, 1, "direction"), "/1/1/4");
}

TEST(PlanParseTest, TupleFormUnderChainOfContactsKeyIgnoresObj) {
  absl::StatusOr<ContactChain> chain = LoadContactChainFile(PlanDataPath("sceneplan_medium.json"));
  ASSERT_TRUE(chain.ok()) << chain.status();
  EXPECT_EQ(chain->form, ChainForm::kTuple);
  ASSERT_EQ(chain->steps.size(), 8u);
  EXPECT_EQ(chain->steps[1].pairs[0].part, "seat soft surface42");
  EXPECT_EQ(chain->steps[1].pairs[0].where, "/chain of contacts/1/0");
  EXPECT_TRUE(chain->steps[7].pairs[0].IsGetClose());
}

TEST(PlanParseTest, RoundTripSimhumanForm) {
  absl::StatusOr<ContactChain> a = LoadContactChainFile(PlanDataPath("chain_simhuman.json"));
  ASSERT_TRUE(a.ok()) << a.status();
  nlohmann::json ja = ContactChainToJson(*a);
  absl::StatusOr<ContactChain> b = ParseContactChainJson(ja, "<roundtrip>");
  ASSERT_TRUE(b.ok()) << b.status();
  EXPECT_EQ(ContactChainToJson(*b), ja);
  // optional keys are written only when set; get-close pairs carry no contact
  EXPECT_FALSE(ja["steps"][3].contains("label"));
  EXPECT_EQ(ja["steps"][3]["pairs"][0]["agent"], 1);
  EXPECT_FALSE(ja["steps"][1]["pairs"][0].contains("agent"));
  EXPECT_FALSE(ja["steps"][0]["pairs"][0].contains("contact"));
  EXPECT_EQ(ja["steps"][2]["pairs"][2]["contact"], "not contact");
}

TEST(PlanParseTest, RoundTripTupleFormToSimhumanForm) {
  absl::StatusOr<ContactChain> a = LoadContactChainFile(PlanDataPath("sceneplan_medium.json"));
  ASSERT_TRUE(a.ok()) << a.status();
  nlohmann::json ja = ContactChainToJson(*a);
  absl::StatusOr<ContactChain> b = ParseContactChainJson(ja, "<roundtrip>");
  ASSERT_TRUE(b.ok()) << b.status();
  EXPECT_EQ(b->form, ChainForm::kSimhuman);
  EXPECT_EQ(ContactChainToJson(*b), ja);
  EXPECT_EQ(ja["steps"][0]["pairs"][0],
            nlohmann::json::parse(R"({"object": "chair000", "part": "none", "joint": "none",
                                      "direction": "front"})"));
}

TEST(PlanParseTest, GetCloseAcceptsExplicitNoneContactInSimhumanForm) {
  absl::StatusOr<ContactChain> chain = ParseContactChain(
      R"({"steps": [{"pairs": [{"object": "bed001", "part": "none", "joint": "none",
                                "contact": "none", "direction": "left"}]}]})",
      "<string>");
  ASSERT_TRUE(chain.ok()) << chain.status();
  EXPECT_TRUE(chain->steps[0].pairs[0].IsGetClose());
  EXPECT_EQ(chain->steps[0].pairs[0].direction, Direction::kLeft);
}

TEST(PlanParseTest, MalformedSyntaxNamesLineAndColumn) {
  std::string msg = LoadError("malformed_syntax.json");
  EXPECT_THAT(msg, HasSubstr("malformed_syntax.json:4:"));
  EXPECT_THAT(msg, HasSubstr("invalid JSON"));
}

TEST(PlanParseTest, MalformedUnknownKey) {
  std::string msg = LoadError("malformed_unknown_key.json");
  EXPECT_THAT(msg, HasSubstr("/steps/0/pairs/0: unknown key 'force_n'"));
  EXPECT_THAT(msg, HasSubstr("object, part, joint, contact, direction, agent"));
}

TEST(PlanParseTest, MalformedUnknownTopKey) {
  std::string msg = LoadError("malformed_unknown_top_key.json");
  EXPECT_THAT(msg, HasSubstr("(root): unknown key 'version'"));
}

TEST(PlanParseTest, MalformedUnknownJoint) {
  // any joint name parses (an agent's body may have more points); grounding names the culprit
  ASSERT_TRUE(LoadContactChainFile(PlanDataPath("malformed_unknown_joint.json")).ok());
  absl::StatusOr<ContactChain> chain =
      LoadAndGroundFile(PlanDataPath("malformed_unknown_joint.json"), fixtures::MakeTestScene());
  ASSERT_FALSE(chain.ok());
  std::string msg(chain.status().message());
  EXPECT_THAT(msg, HasSubstr("malformed_unknown_joint.json"));
  EXPECT_THAT(msg, HasSubstr("/steps/0/pairs/0/joint: unknown joint 'butt' for human 0"));
  EXPECT_THAT(msg, HasSubstr("valid joints: pelvis, torso, head, left shoulder"));
}

TEST(PlanParseTest, MalformedBadContactType) {
  std::string msg = LoadError("malformed_bad_contact.json");
  EXPECT_THAT(msg, HasSubstr("/0/0/3: unknown contact type 'touch'"));
  EXPECT_THAT(msg, HasSubstr("valid contact types: contact, not contact, not care"));
}

TEST(PlanParseTest, MalformedBadDirection) {
  std::string msg = LoadError("malformed_bad_direction.json");
  EXPECT_THAT(msg, HasSubstr("/steps/0/pairs/0/direction: unknown direction 'above'"));
  EXPECT_THAT(msg, HasSubstr("valid directions: up, down, front, back, left, right, none"));
}

TEST(PlanParseTest, MalformedEmptyPlan) {
  std::string msg = LoadError("malformed_empty_plan.json");
  EXPECT_THAT(msg, HasSubstr("/steps: plan has no steps"));
}

TEST(PlanParseTest, MalformedEmptyStep) {
  std::string msg = LoadError("malformed_empty_step.json");
  EXPECT_THAT(msg, HasSubstr("/steps/1/pairs: step has no pairs"));
}

TEST(PlanParseTest, MalformedTupleArity) {
  std::string msg = LoadError("malformed_tuple_arity.json");
  EXPECT_THAT(msg, HasSubstr("/chain of contacts/1/0: a contact pair needs 5 elements"));
  EXPECT_THAT(msg, HasSubstr("[object, part, joint, contact, direction], got 4"));
}

TEST(PlanParseTest, MalformedTupleNonString) {
  std::string msg = LoadError("malformed_tuple_non_string.json");
  EXPECT_THAT(msg, HasSubstr("/0/0/2: expected a string (joint), got number"));
}

TEST(PlanParseTest, MalformedMissingContact) {
  std::string msg = LoadError("malformed_missing_contact.json");
  EXPECT_THAT(msg, HasSubstr("/steps/0/pairs/0: missing required string 'contact'"));
  EXPECT_THAT(msg, HasSubstr("contact, not contact, not care"));
}

TEST(PlanParseTest, MalformedGetCloseDirection) {
  std::string msg = LoadError("malformed_get_close_direction.json");
  EXPECT_THAT(msg, HasSubstr("/0/0/4: a get-close pair"));
  EXPECT_THAT(msg, HasSubstr("valid directions: front, back, left, right; got 'up'"));
}

TEST(PlanParseTest, MalformedGetCloseContact) {
  std::string msg = LoadError("malformed_get_close_contact.json");
  EXPECT_THAT(msg, HasSubstr("/0/0/3: a get-close pair (part and joint 'none') needs contact "
                             "'none', got 'contact'"));
}

TEST(PlanParseTest, MalformedPartialNone) {
  std::string msg = LoadError("malformed_partial_none.json");
  EXPECT_THAT(msg, HasSubstr("/0/0/1: part is 'none' but joint is 'pelvis'"));
}

TEST(PlanParseTest, MalformedSelfContact) {
  std::string msg = LoadError("malformed_self_contact.json");
  EXPECT_THAT(msg, HasSubstr("/0/0/1: joint 'right hand' cannot contact itself"));
}

TEST(PlanParseTest, MalformedNegativeAgent) {
  std::string msg = LoadError("malformed_agent_negative.json");
  EXPECT_THAT(msg, HasSubstr("/steps/0/pairs/0/agent: agent index must be >= 0, got -1"));
}

TEST(PlanParseTest, MalformedTopLevel) {
  std::string msg = LoadError("malformed_top_level.json");
  EXPECT_THAT(msg, HasSubstr("expected key 'steps'"));
  EXPECT_THAT(msg, HasSubstr("'chain of contacts'"));
}

TEST(PlanParseTest, MissingFileIsNotFound) {
  absl::StatusOr<ContactChain> chain = LoadContactChainFile(PlanDataPath("no_such_plan.json"));
  ASSERT_FALSE(chain.ok());
  EXPECT_EQ(chain.status().code(), absl::StatusCode::kNotFound);
  EXPECT_THAT(std::string(chain.status().message()), HasSubstr("no_such_plan.json"));
}

TEST(PlanParseTest, WrongTypesNameThePointer) {
  struct Case {
    const char* text;
    const char* expect;
  };
  const Case cases[] = {
      {R"("sit")", "(root): expected a JSON object or array, got string"},
      {R"({"steps": {}})", "/steps: expected an array of steps, got object"},
      {R"({"steps": [[]]})", "/steps/0: expected a JSON object, got array"},
      {R"({"steps": [{"pairs": [{"object": 7}]}]})", "/steps/0/pairs/0/object: expected a string"},
      {R"({"steps": [{"label": 3, "pairs": []}]})", "/steps/0/label: expected a string"},
      {R"({"steps": [{"pairs": [{"object": "chair000", "part": "seat", "joint": "pelvis",
           "contact": "contact", "direction": "up", "agent": 0.5}]}]})",
       "/steps/0/pairs/0/agent: expected a non-negative integer"},
      {R"([["chair000", "none", "none", "none", "front"]])",
       "/0/0: expected a contact pair [object, part, joint, contact, direction], got string"},
      {R"([{"object": "chair000"}])", "/0: expected a step (an array of 5-element pairs)"},
      {R"([])", "(root): plan has no steps"},
      {R"({"chain of contacts": [[]]})", "/chain of contacts/0: step has no pairs"},
      {R"([[["none", "none", "none", "none", "front"]]])", "/0/0/0: every pair needs an object"},
      {R"([[["chair000", "seat", "pelvis", "none", "up"]]])",
       "/0/0/3: contact 'none' is only valid in a get-close pair"},
  };
  for (const Case& c : cases) {
    absl::StatusOr<ContactChain> chain = ParseContactChain(c.text, "<string>");
    ASSERT_FALSE(chain.ok()) << c.text;
    EXPECT_THAT(std::string(chain.status().message()), HasSubstr(c.expect)) << c.text;
    EXPECT_THAT(std::string(chain.status().message()), HasSubstr("<string>: ")) << c.text;
  }
}

TEST(PlanParseTest, CheckPairShapeOnChainsBuiltInCode) {
  ContactChain chain;
  ContactStep step;
  ContactPair pair;
  pair.object = "chair000";
  pair.part = "none";
  pair.direction = Direction::kDown;
  step.pairs.push_back(pair);
  chain.steps.push_back(step);
  absl::Status s = CheckPairShape(chain, 0, 0);
  EXPECT_THAT(std::string(s.message()), HasSubstr("/steps/0/pairs/0/direction: a get-close"));
  chain.steps[0].pairs[0].direction = Direction::kBack;
  EXPECT_TRUE(CheckPairShape(chain, 0, 0).ok());
}

}  // namespace
}  // namespace simhuman::plan
