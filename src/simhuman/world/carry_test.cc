#include "simhuman/world/carry.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "simhuman/world/objects.h"
#include "simhuman/world/scene.h"

namespace simhuman::world {
namespace {

using ::testing::HasSubstr;

constexpr double kTolM = 1e-9;

core::CatalogObject Build(ObjectSpec spec) {
  if (spec.id.empty()) spec.id = spec.type + "000";
  core::StatusOr<core::CatalogObject> o = BuildObject(spec);
  EXPECT_TRUE(o.ok()) << o.status();
  return o.ok() ? *o : core::CatalogObject{};
}

ObjectSpec Spec(const std::string& type, std::optional<double> mass_kg = std::nullopt) {
  ObjectSpec s;
  s.type = type;
  s.mass_kg = mass_kg;
  return s;
}

TEST(CarryTest, HalfMetreBoxHasOneCarrierAtItsBackHandsOnItsSides) {
  ObjectSpec s = Spec("box", 8.0);
  s.size = {{"depth", 0.5}, {"width", 0.5}, {"height", 0.5}};
  const core::CatalogObject box = Build(s);
  ASSERT_TRUE(box.carry.carryable()) << box.carry.not_carryable;
  EXPECT_EQ(box.carry.min_carriers(), 1);
  EXPECT_EQ(box.carry.max_carriers(), 1);
  const core::CarryHold& h = box.carry.ForTeam(1)->holds[0];
  // stand 0.2 m beyond the back face, facing +x: its left hand is on the +y face
  EXPECT_NEAR(h.stand_local.x(), -0.25 - kCarryStandOffM, kTolM);
  EXPECT_NEAR(h.stand_local.y(), 0.0, kTolM);
  EXPECT_NEAR(h.stand_local.z(), 0.0, kTolM);
  EXPECT_NEAR(h.facing_local_rad, 0.0, kTolM);
  EXPECT_EQ(h.left_part, "left side");
  EXPECT_EQ(h.right_part, "right side");
  EXPECT_TRUE(h.left_hand_local.isApprox(Eigen::Vector3d(0, 0.25, 0.25)));
  EXPECT_TRUE(h.right_hand_local.isApprox(Eigen::Vector3d(0, -0.25, 0.25)));
  EXPECT_TRUE(h.held_local.isApprox(Eigen::Vector3d(0, 0, 0.25)));
}

TEST(CarryTest, LongBoxIsForTeamsOfTwoToFourHeldAtItsEnds) {
  const core::CatalogObject lb = Build(Spec("long_box"));
  EXPECT_TRUE(lb.movable);
  EXPECT_DOUBLE_EQ(lb.mass_kg, 25.0);
  ASSERT_EQ(lb.carry.layouts.size(), 3u);
  EXPECT_EQ(lb.carry.min_carriers(), 2);
  EXPECT_EQ(lb.carry.max_carriers(), 4);
  EXPECT_EQ(lb.carry.ForTeam(1), nullptr);
  const core::CarryLayout& two = *lb.carry.ForTeam(2);
  // carrier 0 at the +x end facing -x (its left is -y), carrier 1 at the -x end facing +x
  EXPECT_NEAR(two.holds[0].stand_local.x(), 1.0 + kCarryStandOffM, kTolM);
  EXPECT_NEAR(std::cos(two.holds[0].facing_local_rad), -1.0, kTolM);
  EXPECT_EQ(two.holds[0].left_part, "right side");
  EXPECT_NEAR(two.holds[0].left_hand_local.x(), 1.0 - kEndHoldInsetM, kTolM);
  EXPECT_NEAR(two.holds[0].left_hand_local.y(), -0.25, kTolM);
  EXPECT_NEAR(two.holds[1].stand_local.x(), -1.0 - kCarryStandOffM, kTolM);
  EXPECT_EQ(two.holds[1].left_part, "left side");
  // held points: the centres of the two ends' hand pairs
  EXPECT_NEAR(two.holds[0].held_local.x(), 1.0 - kEndHoldInsetM, kTolM);
  EXPECT_NEAR(two.holds[1].held_local.x(), -(1.0 - kEndHoldInsetM), kTolM);
  const core::CarryLayout& four = *lb.carry.ForTeam(4);
  EXPECT_NEAR(four.holds[2].stand_local.y(), 0.25 + kCarryStandOffM, kTolM);
  EXPECT_NEAR(four.holds[3].stand_local.y(), -0.25 - kCarryStandOffM, kTolM);
  EXPECT_EQ(four.holds[2].left_part, "left side");
  EXPECT_EQ(four.holds[2].right_part, "left side");
}

TEST(CarryTest, TabletopBoxesStaticFurnitureAndBedsAreNotCarried) {
  ObjectSpec small = Spec("box", 0.3);
  small.size = {{"depth", 0.08}, {"width", 0.08}, {"height", 0.08}};
  const core::CatalogObject cube = Build(small);
  EXPECT_FALSE(cube.carry.carryable());
  EXPECT_THAT(cube.carry.not_carryable, HasSubstr("too small"));
  ObjectSpec wide = Spec("box", 5.0);
  wide.size = {{"depth", 1.0}, {"width", 1.0}, {"height", 0.3}};
  EXPECT_THAT(Build(wide).carry.not_carryable, HasSubstr("too large"));
  const core::CatalogObject armchair = Build(Spec("armchair"));
  EXPECT_FALSE(armchair.movable);
  EXPECT_THAT(armchair.carry.not_carryable, HasSubstr("static"));
  EXPECT_FALSE(Build(Spec("bed", 60.0)).carry.carryable());
  EXPECT_FALSE(Build(Spec("laptop", 2.0)).carry.carryable());
  EXPECT_THAT(Build(Spec("sphere")).carry.not_carryable, HasSubstr("one hand"));
}

TEST(CarryTest, MovableFurnitureHasHoldsOnItsParts) {
  // the armchair's carrier stands in front facing -x: its left hand goes on the right arm
  const core::CatalogObject armchair = Build(Spec("armchair", *DefaultMovableMassKg("armchair")));
  ASSERT_TRUE(armchair.carry.carryable());
  const core::CarryHold& a = armchair.carry.ForTeam(1)->holds[0];
  EXPECT_EQ(a.left_part, "right arm");
  EXPECT_EQ(a.right_part, "left arm");
  EXPECT_NEAR(a.left_hand_local.z(), DefaultSizes("armchair").at("arm_height"), kTolM);
  EXPECT_GT(a.stand_local.x(), armchair.LocalBounds().second.x());
  const core::CatalogObject sofa = Build(Spec("sofa", 35.0));
  EXPECT_EQ(sofa.carry.min_carriers(), 2);
  EXPECT_EQ(sofa.carry.max_carriers(), 2);
  const core::CarryLayout& ends = *sofa.carry.ForTeam(2);
  EXPECT_EQ(ends.holds[0].left_part, "left arm");
  EXPECT_EQ(ends.holds[1].left_part, "right arm");
  EXPECT_NEAR(ends.holds[0].stand_local.y(), sofa.LocalBounds().second.y() + kCarryStandOffM,
              kTolM);
  for (const char* type : {"table", "high_stool", "chair", "stool"}) {
    const core::CatalogObject o = Build(Spec(type, *DefaultMovableMassKg(type)));
    ASSERT_TRUE(o.carry.carryable()) << type << ": " << o.carry.not_carryable;
    const core::CarryHold& h = o.carry.ForTeam(1)->holds[0];
    EXPECT_NE(o.FindPart(h.left_part), nullptr) << type;
    // the carrier faces -x, so its left hand is on the -y side
    EXPECT_LT(h.left_hand_local.y(), h.right_hand_local.y()) << type;
  }
}

TEST(CarryTest, TeamCapacityAndDefaultMasses) {
  EXPECT_DOUBLE_EQ(core::TeamCapacityKg(0), 0.0);
  EXPECT_DOUBLE_EQ(core::TeamCapacityKg(1), 13.0);
  EXPECT_DOUBLE_EQ(core::TeamCapacityKg(2), 40.0);
  EXPECT_DOUBLE_EQ(core::TeamCapacityKg(4), 80.0);
  // one carrier can lift each single-carrier piece of furniture, two the sofa
  for (const char* type : {"chair", "armchair", "stool", "high_stool", "table"}) {
    EXPECT_LE(*DefaultMovableMassKg(type), core::TeamCapacityKg(1)) << type;
  }
  EXPECT_LE(*DefaultMovableMassKg("sofa"), core::TeamCapacityKg(2));
  EXPECT_FALSE(DefaultMovableMassKg("bed"));
  EXPECT_FALSE(DefaultMovableMassKg("box"));
}

}  // namespace
}  // namespace simhuman::world
