#include "simhuman/core/scene_catalog.h"

#include <gtest/gtest.h>

namespace simhuman::core {
namespace {

// the canonical form with trailing digits kept: what plan/ matches exact part names, joints,
// contact types and directions under
TEST(NormalizeNameTest, KeepingDigitsTrimsAndLowersOnly) {
  EXPECT_EQ(NormalizeName("Arm_Sofa_Style44", TrailingDigits::kKeep), "arm sofa style44");
  EXPECT_EQ(NormalizeName("  Left_Hand ", TrailingDigits::kKeep), "left hand");
  EXPECT_EQ(NormalizeName("mattress25 ", TrailingDigits::kKeep), "mattress25");
  EXPECT_EQ(NormalizeName("mattress 25", TrailingDigits::kKeep), "mattress 25");
  EXPECT_EQ(NormalizeName("NOT_CONTACT", TrailingDigits::kKeep), "not contact");
  EXPECT_EQ(NormalizeName(" _ ", TrailingDigits::kKeep), "");
  EXPECT_EQ(NormalizeName("", TrailingDigits::kKeep), "");
  // only ' ' (and '_') count as spaces
  EXPECT_EQ(NormalizeName("\tup", TrailingDigits::kKeep), "\tup");
}

// dropping digits (the default) also drops spaces between trailing digits
TEST(NormalizeNameTest, DroppingDigitsIsTheDefault) {
  EXPECT_EQ(NormalizeName("Arm_Sofa_Style44"), "arm sofa style");
  EXPECT_EQ(NormalizeName("mattress 2 5 "), "mattress");
  EXPECT_EQ(NormalizeName("42"), "");
  EXPECT_EQ(NormalizeName("1st seat"), "1st seat");
  EXPECT_EQ(NormalizeName("Seat_Soft_Surface42", TrailingDigits::kDrop), "seat soft surface");
}

}  // namespace
}  // namespace simhuman::core
