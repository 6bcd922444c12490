#include "simhuman/plan/carry.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "simhuman/core/footprint.h"
#include "simhuman/plan/contact_chain.h"
#include "simhuman/plan/metrics.h"
#include "simhuman/plan/test_scene.h"
#include "simhuman/plan/validate.h"

namespace simhuman::plan {
namespace {

using fixtures::Box;
using ::testing::HasSubstr;

core::CarryHold Hold(double stand_x, double facing, double hand_x, double half_y, double z,
                     const std::string& left, const std::string& right) {
  core::CarryHold h;
  h.stand_local = {stand_x, 0, 0};
  h.facing_local_rad = facing;
  const double sign = std::cos(facing) > 0 ? 1.0 : -1.0;  // facing +x: left is +y
  h.left_hand_local = {hand_x, sign * half_y, z};
  h.right_hand_local = {hand_x, -sign * half_y, z};
  h.left_part = left;
  h.right_part = right;
  h.held_local = {hand_x, 0, z};
  return h;
}

// a box of half extents (hx, 0.25, 0.25) at `pos`, carried by one (hx <= 0.5) or two carriers
core::CatalogObject MakeCarryBox(const std::string& id, const Eigen::Vector3d& pos, double hx,
                                 double mass_kg) {
  core::CatalogObject o;
  o.id = id;
  o.type = "box";
  o.pose = core::Pose::FromYaw(pos, 0.0);
  o.movable = true;
  o.mass_kg = mass_kg;
  o.parts.push_back(fixtures::Part("left side", {}, Box({0, 0.24, 0.25}, {hx, 0.01, 0.25})));
  o.parts.push_back(fixtures::Part("right side", {}, Box({0, -0.24, 0.25}, {hx, 0.01, 0.25})));
  o.shapes.push_back(Box({0, 0, 0.25}, {hx, 0.25, 0.25}));
  core::CarryLayout layout;
  if (hx <= 0.5) {
    layout.holds.push_back(Hold(-hx - 0.2, 0.0, 0.0, 0.25, 0.25, "left side", "right side"));
  } else {
    layout.holds.push_back(Hold(hx + 0.2, M_PI, hx - 0.25, 0.25, 0.25, "right side", "left side"));
    layout.holds.push_back(Hold(-hx - 0.2, 0.0, -hx + 0.25, 0.25, 0.25, "left side", "right side"));
  }
  o.carry.layouts.push_back(layout);
  return o;
}

// chair000 at the origin, bed001 at (3, 0) turned 90 degrees (x 2.5..3.5, y -1..1), box002 (a
// 0.5 m cube, 8 kg) at (0, 3), long003 (2 m, 30 kg) at (0, -3); two humans
core::SceneCatalog CarryScene() {
  core::SceneCatalog scene = fixtures::MakeTestScene();
  scene.objects.push_back(MakeCarryBox("box002", {0, 3, 0}, 0.25, 8.0));
  scene.objects.push_back(MakeCarryBox("long003", {0, -3, 0}, 1.0, 30.0));
  scene.agents.resize(2);
  return scene;
}

std::string Plan(const std::string& carry) {
  return R"({"steps": [{"label": "carry", "carry": )" + carry + "}]}";
}

std::string GroundError(const std::string& carry, const core::SceneCatalog& scene) {
  absl::StatusOr<ContactChain> chain = ParseAndGround(Plan(carry), "plan.json", scene);
  EXPECT_FALSE(chain.ok()) << carry;
  if (chain.ok()) return {};
  EXPECT_EQ(chain.status().code(), absl::StatusCode::kInvalidArgument);
  return std::string(chain.status().message());
}

TEST(PlanCarryTest, ParsesEveryDestinationAndWritesItBack) {
  const std::string text = R"({"steps": [
    {"label": "lift", "carry": {"object": "box002", "carriers": [0]}},
    {"carry": {"object": "box002", "carriers": [0], "to": "here"}},
    {"carry": {"object": "box002", "carriers": [{"agent": 1, "hold": 0}],
               "to": {"point": [1.5, 2], "yaw_deg": 90}}},
    {"carry": {"object": "long003", "carriers": [0, 1], "to": {"beside": "bed001", "side": "Left"}}},
    {"pairs": [{"object": "chair000", "part": "none", "joint": "none", "direction": "front"}]}]})";
  absl::StatusOr<ContactChain> chain = ParseContactChain(text, "plan.json");
  ASSERT_TRUE(chain.ok()) << chain.status();
  ASSERT_EQ(chain->steps.size(), 5u);
  EXPECT_EQ(chain->steps[0].carry->to.kind, CarryTarget::kHold);
  EXPECT_EQ(chain->steps[1].carry->to.kind, CarryTarget::kHere);
  const CarryStep& point = *chain->steps[2].carry;
  EXPECT_EQ(point.to.kind, CarryTarget::kFloor);
  EXPECT_DOUBLE_EQ(point.to.x_m, 1.5);
  EXPECT_NEAR(*point.to.yaw_rad, M_PI / 2, 1e-12);
  EXPECT_EQ(point.carriers[0].agent, 1);
  EXPECT_EQ(point.carriers[0].hold, 0);
  EXPECT_EQ(chain->steps[3].carry->to.side, Direction::kLeft);
  EXPECT_FALSE(chain->steps[4].carry.has_value());
  EXPECT_EQ(CarrySummary(*chain->steps[3].carry), "carry long003 by 0,1 to beside bed001 left");
  EXPECT_EQ(CarrySummary(*chain->steps[0].carry), "carry box002 by 0 and hold");
  // written and read again: the same chain
  absl::StatusOr<ContactChain> again =
      ParseContactChainJson(ContactChainToJson(*chain), "again.json");
  ASSERT_TRUE(again.ok()) << again.status();
  EXPECT_EQ(ContactChainToJson(*again), ContactChainToJson(*chain));
}

TEST(PlanCarryTest, MalformedCarryStepsNameTheField) {
  auto error = [](const std::string& step) {
    absl::StatusOr<ContactChain> c =
        ParseContactChain(R"({"steps": [)" + step + "]}", "malformed_carry.json");
    EXPECT_FALSE(c.ok()) << step;
    return c.ok() ? std::string() : std::string(c.status().message());
  };
  EXPECT_THAT(error(R"({"carry": {"object": "box002", "carriers": [0]}, "pairs": []})"),
              HasSubstr("/steps/0/pairs: a carry step takes no 'pairs'"));
  EXPECT_THAT(error(R"({"carry": {"object": "box002", "carriers": []}})"),
              HasSubstr("/steps/0/carry/carriers"));
  EXPECT_THAT(error(R"({"carry": {"object": "box002", "carriers": [-1]}})"),
              HasSubstr("/steps/0/carry/carriers/0"));
  EXPECT_THAT(error(R"({"carry": {"object": "box002", "carriers": [0], "to": "there"}})"),
              HasSubstr("unknown destination 'there'"));
  EXPECT_THAT(error(R"({"carry": {"object": "box002", "carriers": [0], "to": {"beside": "bed001",
                "side": "up"}}})"),
              HasSubstr("/steps/0/carry/to/side: unknown side 'up'; valid sides: front, back"));
  EXPECT_THAT(error(R"({"carry": {"object": "box002", "carriers": [0], "to": {"point": [1]}}})"),
              HasSubstr("/steps/0/carry/to/point"));
  EXPECT_THAT(error(R"({"carry": {"object": "box002", "carriers": [0], "weight": 3}})"),
              HasSubstr("weight"));
}

TEST(PlanCarryTest, GroundsBesideAClearSideAndWritesTheHandPairs) {
  const core::SceneCatalog scene = CarryScene();
  absl::StatusOr<ContactChain> chain = ParseAndGround(
      Plan(R"({"object": "box002", "carriers": [1], "to": {"beside": "bed001"}})"), "p", scene);
  ASSERT_TRUE(chain.ok()) << chain.status();
  const ContactStep& step = chain->steps[0];
  ASSERT_TRUE(step.carry->goal.has_value());
  ASSERT_TRUE(step.carry->goal_side.has_value());
  EXPECT_EQ(step.carry->carriers[0].hold, 0);
  // beside the bed, clear of it: the box's 0.25 m half size plus the gap
  const Eigen::Vector2d goal = step.carry->goal->pos.head<2>();
  EXPECT_GT(core::FootprintDistance(*scene.Find("bed001"), goal), 0.25 + 0.1);
  EXPECT_LT(core::FootprintDistance(*scene.Find("bed001"), goal), 0.25 + 0.2);
  ASSERT_EQ(step.pairs.size(), 2u);
  for (const ContactPair& p : step.pairs) {
    EXPECT_EQ(p.agent, 1);
    EXPECT_EQ(p.object, "box002");
    EXPECT_EQ(p.type, ContactType::kContact);
  }
  EXPECT_EQ(step.pairs[0].joint, core::BodyJoint::kLeftHand);
  EXPECT_EQ(step.pairs[0].part, "left side");
  EXPECT_EQ(step.pairs[0].direction, Direction::kLeft);
  EXPECT_EQ(step.pairs[1].joint, core::BodyJoint::kRightHand);
  EXPECT_EQ(step.pairs[1].direction, Direction::kRight);
}

// a carry step to a floor point completes only with the box down at its goal and let go
TEST(PlanCarryTest, ACarryStepCompletesWithTheObjectDownAtItsGoalAndReleased) {
  core::SceneCatalog scene = CarryScene();
  absl::StatusOr<ContactChain> chain = ParseAndGround(
      Plan(R"({"object": "box002", "carriers": [0], "to": {"point": [-2, 3]}})"), "p", scene);
  ASSERT_TRUE(chain.ok()) << chain.status();
  const ContactStep& step = chain->steps[0];
  ASSERT_TRUE(step.carry->goal.has_value());
  core::SceneCatalog live = CarryScene();  // the box still at its start
  core::CatalogObject* box = live.Find("box002");
  std::vector<BodyPoints> agents(2);
  for (BodyPoints& b : agents) {
    for (Eigen::Vector3d& p : b.pos_world) p = Eigen::Vector3d(5, 5, 1);  // far from the box
  }
  const PairParams params;
  EXPECT_FALSE(EvaluateStep(step, live, agents, params).complete);
  box->pose = core::Pose::FromYaw(step.carry->goal->pos + Eigen::Vector3d(0.1, 0.05, 0), 0.3);
  EXPECT_TRUE(EvaluateStep(step, live, agents, params).complete);
  // still held: the hands on its sides
  BodyPoints& h = agents[0];
  h.at(core::BodyJoint::kLeftHand) = box->pose.Apply({0, 0.3, 0.25});
  h.at(core::BodyJoint::kRightHand) = box->pose.Apply({0, -0.3, 0.25});
  EXPECT_FALSE(EvaluateStep(step, live, agents, params).complete);
  h.at(core::BodyJoint::kLeftHand) = h.at(core::BodyJoint::kRightHand) = {5, 5, 1};
  // off the floor, or too far from the goal
  box->pose.pos.z() = 0.2;
  EXPECT_FALSE(EvaluateStep(step, live, agents, params).complete);
  box->pose = core::Pose::FromYaw(step.carry->goal->pos + Eigen::Vector3d(0.25, 0, 0), 0);
  EXPECT_FALSE(EvaluateStep(step, live, agents, params).complete);
}

TEST(PlanCarryTest, RefusesWhatTheTeamCannotDo) {
  core::SceneCatalog scene = CarryScene();
  EXPECT_THAT(GroundError(R"({"object": "chair000", "carriers": [0]})", scene),
              HasSubstr("plan.json: /steps/0/carry/object: chair000 (chair) cannot be carried"));
  EXPECT_THAT(GroundError(R"({"object": "sofa", "carriers": [0]})", scene),
              HasSubstr("carryable objects: box002, long003"));
  std::string e = GroundError(R"({"object": "box002", "carriers": [0, 1]})", scene);
  EXPECT_THAT(e, HasSubstr("/steps/0/carry/carriers: 2 carriers, but box002 (box) has held "
                           "points for at most 1"));
  EXPECT_THAT(GroundError(R"({"object": "long003", "carriers": [0]})", scene),
              HasSubstr("needs 2 or more carriers"));
  EXPECT_THAT(GroundError(R"({"object": "box002", "carriers": [2]})", scene),
              HasSubstr("/steps/0/carry/carriers/0: agent index 2 out of range; the scene has 2 "
                        "human(s), valid indices are 0..1"));
  EXPECT_THAT(GroundError(R"({"object": "long003", "carriers": [1, 1]})", scene),
              HasSubstr("listed twice"));
  EXPECT_THAT(
      GroundError(R"({"object": "long003", "carriers": [{"agent": 0, "hold": 2}, 1]})", scene),
      HasSubstr("/steps/0/carry/carriers/0/hold: hold 2 out of range"));
  scene.Find("box002")->mass_kg = 20.0;
  e = GroundError(R"({"object": "box002", "carriers": [0]})", scene);
  EXPECT_THAT(e, HasSubstr("box002 (box) is too heavy for 1 carrier(s): it weighs 20 kg and a "
                           "team of 1 lifts at most 13 kg"));
  EXPECT_THAT(e, HasSubstr("no team it has held points for (1) can lift it"));
  scene.Find("long003")->mass_kg = 45.0;
  EXPECT_THAT(GroundError(R"({"object": "long003", "carriers": [0, 1]})", scene),
              HasSubstr("lifts at most 40 kg"));
}

TEST(PlanCarryTest, RefusesDestinationsInsideObjectsOffTheFloorOrUnreachable) {
  const core::SceneCatalog scene = CarryScene();
  EXPECT_THAT(
      GroundError(R"({"object": "box002", "carriers": [0], "to": {"point": [3, 0.5]}})", scene),
      HasSubstr("/steps/0/carry/to/point: destination (3, 0.5) puts box002 inside bed001 (bed)"));
  EXPECT_THAT(
      GroundError(R"({"object": "box002", "carriers": [0], "to": {"point": [40, 0]}})", scene),
      HasSubstr("off the floor"));
  // clear of the bed, but turned so that its carrier would stand inside the bed
  EXPECT_THAT(GroundError(R"({"object": "box002", "carriers": [0],
                              "to": {"point": [2.15, 0], "yaw_deg": 180}})",
                          scene),
              HasSubstr("unreachable: carrier 0 would stand at (2.6, 0) to put it down, and it "
                        "is inside bed001 (bed)"));
  // without a yaw the box is turned so that its carrier stands clear
  absl::StatusOr<ContactChain> ok = ParseAndGround(
      Plan(R"({"object": "box002", "carriers": [0], "to": {"point": [2.15, 0]}})"), "p", scene);
  ASSERT_TRUE(ok.ok()) << ok.status();
  EXPECT_NEAR(core::PoseYaw(*ok->steps[0].carry->goal), 0.0, 1e-9);
  EXPECT_THAT(
      GroundError(R"({"object": "box002", "carriers": [0], "to": {"beside": "box002"}})", scene),
      HasSubstr("beside itself"));
  EXPECT_THAT(
      GroundError(R"({"object": "box002", "carriers": [0], "to": {"beside": "door"}})", scene),
      HasSubstr("/steps/0/carry/to/beside: unknown object 'door'; valid objects: "));
}

TEST(PlanCarryTest, LaterStepsSeeCarriedObjectsWhereTheyWerePut) {
  const core::SceneCatalog scene = CarryScene();
  const std::string text = R"({"steps": [
    {"carry": {"object": "box002", "carriers": [0], "to": {"point": [0, -5]}}},
    {"carry": {"object": "long003", "carriers": [0, 1], "to": {"point": [0, -5], "yaw_deg": 0}}}
  ]})";
  absl::StatusOr<ContactChain> chain = ParseAndGround(text, "plan.json", scene);
  ASSERT_FALSE(chain.ok());
  EXPECT_THAT(std::string(chain.status().message()),
              HasSubstr("/steps/1/carry/to/point: destination (0, -5) puts long003 inside box002"));
  // the scene itself is not changed
  EXPECT_NEAR(scene.Find("box002")->pose.pos.y(), 3.0, 1e-12);
}

}  // namespace
}  // namespace simhuman::plan
