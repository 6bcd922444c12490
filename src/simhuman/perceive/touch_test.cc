#include "simhuman/perceive/touch.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <cstring>
#include <memory>

namespace simhuman::perceive {
namespace {

constexpr double kRadius = 0.03;

// a contact on the side face of a box (centre `c`, rotation `r`, half width kRadius) whose
// outward normal is the box's local `face`, `along` up its axis and `across` along the face
TouchContact OnFace(const Eigen::Vector3d& c, const Eigen::Matrix3d& r, const Eigen::Vector3d& face,
                    double along, double across) {
  const Eigen::Vector3d tangent = Eigen::Vector3d::UnitZ().cross(face);
  const Eigen::Vector3d local =
      kRadius * face + along * Eigen::Vector3d::UnitZ() + across * tangent;
  return {c + r * local, r * face};
}

double AngleDeg(const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
  return std::acos(std::clamp(a.normalized().dot(b.normalized()), -1.0, 1.0)) * 180 / M_PI;
}

TEST(TouchTest, SideContactsOnTwoFacesGiveTheAxisAndTheCentreAcrossIt) {
  const Eigen::Matrix3d r = (Eigen::AngleAxisd(0.14, Eigen::Vector3d::UnitX()) *
                             Eigen::AngleAxisd(-0.1, Eigen::Vector3d::UnitY()))
                                .toRotationMatrix();
  const Eigen::Vector3d c(0.02, -0.05, 0.1);
  const std::vector<TouchContact> touch = {
      OnFace(c, r, Eigen::Vector3d::UnitX(), 0.02, 0.01),
      OnFace(c, r, Eigen::Vector3d::UnitX(), -0.03, -0.01),
      OnFace(c, r, -Eigen::Vector3d::UnitX(), 0.0, 0.0),
      OnFace(c, r, Eigen::Vector3d::UnitY(), 0.01, 0.015),
      OnFace(c, r, Eigen::Vector3d::UnitY(), -0.02, -0.01),
  };
  const Eigen::Vector3d before = c + Eigen::Vector3d(0.012, -0.009, 0.02);
  Eigen::Vector3d centre = before, up = Eigen::Vector3d::UnitZ();
  const Eigen::Vector3d true_up = r.col(2);
  ASSERT_GT(AngleDeg(up, true_up), 9.0);
  EXPECT_TRUE(RefineHeldByTouch(touch, kRadius, {}, &centre, &up));
  EXPECT_LT(AngleDeg(up, true_up), 0.5);
  // across the axis the centre is where the faces put it; along it, where it was
  const Eigen::Matrix3d across = Eigen::Matrix3d::Identity() - true_up * true_up.transpose();
  EXPECT_LT((across * (centre - c)).norm(), 0.002);
  EXPECT_NEAR((centre - before).dot(up), 0.0, 1e-9);
}

TEST(TouchTest, TwoOppositeFacesLeaveTheTiltAboutTheirNormal) {
  // tilted about y (the faces +-x turn with it) and about x (they do not)
  for (int k : {1, 0}) {
    const Eigen::Vector3d axis = Eigen::Vector3d::Unit(k);
    const Eigen::Matrix3d r = Eigen::AngleAxisd(0.15, axis).toRotationMatrix();
    const Eigen::Vector3d c = Eigen::Vector3d::Zero();
    const std::vector<TouchContact> touch = {
        OnFace(c, r, Eigen::Vector3d::UnitX(), 0.02, 0.0),
        OnFace(c, r, Eigen::Vector3d::UnitX(), -0.02, 0.01),
        OnFace(c, r, -Eigen::Vector3d::UnitX(), 0.0, 0.0),
    };
    Eigen::Vector3d centre = c, up = Eigen::Vector3d::UnitZ();
    EXPECT_TRUE(RefineHeldByTouch(touch, kRadius, {}, &centre, &up));
    if (axis.y() > 0) {
      EXPECT_LT(AngleDeg(up, r.col(2)), 0.5);
    } else {
      EXPECT_LT(AngleDeg(up, Eigen::Vector3d::UnitZ()), 0.5) << "no contact says this tilt";
    }
  }
}

TEST(TouchTest, WithoutSideContactsNothingChanges) {
  const std::vector<TouchContact> top = {
      {Eigen::Vector3d(0, 0, 0.08), Eigen::Vector3d::UnitZ()},
      {Eigen::Vector3d(0.01, 0, 0.08), Eigen::Vector3d(0.3, 0, 1).normalized()}};
  Eigen::Vector3d centre(0.01, 0.02, 0.03), up = Eigen::Vector3d(0.1, 0, 1).normalized();
  const Eigen::Vector3d c0 = centre, u0 = up;
  EXPECT_FALSE(RefineHeldByTouch(top, kRadius, {}, &centre, &up));
  EXPECT_FALSE(RefineHeldByTouch({}, kRadius, {}, &centre, &up));
  EXPECT_EQ(centre, c0);
  EXPECT_EQ(up, u0);
}

TEST(TouchTest, TouchThatWouldTurnOrShiftTooFarIsNotBelieved) {
  // a box tilted 17 degrees from the estimate (its faces within side_cos of square to it): a
  // held box turns that far in the grip, and touch is believed; with a 0.2 rad bound it is not
  const Eigen::Matrix3d r = Eigen::AngleAxisd(0.3, Eigen::Vector3d::UnitY()).toRotationMatrix();
  std::vector<TouchContact> touch = {
      OnFace(Eigen::Vector3d::Zero(), r, Eigen::Vector3d::UnitX(), 0.0, 0.0),
      OnFace(Eigen::Vector3d::Zero(), r, -Eigen::Vector3d::UnitX(), 0.0, 0.0),
      OnFace(Eigen::Vector3d::Zero(), r, Eigen::Vector3d::UnitY(), 0.0, 0.0)};
  Eigen::Vector3d centre = Eigen::Vector3d::Zero(), up = Eigen::Vector3d::UnitZ();
  TouchRefineOptions narrow;
  narrow.max_turn_rad = 0.2;
  EXPECT_FALSE(RefineHeldByTouch(touch, kRadius, narrow, &centre, &up));
  EXPECT_EQ(up, Eigen::Vector3d::UnitZ());
  EXPECT_TRUE(RefineHeldByTouch(touch, kRadius, {}, &centre, &up));
  EXPECT_LT(AngleDeg(up, r.col(2)), 0.5);
  // faces 9 cm from where the estimate puts them
  touch = {OnFace(Eigen::Vector3d(0.09, 0, 0), Eigen::Matrix3d::Identity(),
                  Eigen::Vector3d::UnitX(), 0.0, 0.0)};
  centre = Eigen::Vector3d::Zero();
  up = Eigen::Vector3d::UnitZ();
  EXPECT_FALSE(RefineHeldByTouch(touch, kRadius, {}, &centre, &up));
  EXPECT_EQ(centre, Eigen::Vector3d::Zero());
  // 5 cm is a slip in the grip, and believed: the face lies a half width from the new centre
  touch = {OnFace(Eigen::Vector3d(0.05, 0, 0), Eigen::Matrix3d::Identity(),
                  Eigen::Vector3d::UnitX(), 0.0, 0.0)};
  EXPECT_TRUE(RefineHeldByTouch(touch, kRadius, {}, &centre, &up));
  EXPECT_NEAR(centre.x(), 0.05, 0.005);
}

TEST(TouchTest, HandTouchReadsContactsInTheHandsFrameFacingOutOfTheObject) {
  // a hand turned 90 degrees about z with a finger pressed into a box's +x face
  const char* xml = R"(
<mujoco>
  <worldbody>
    <body name="box" pos="0 0 0.1"><freejoint/><geom type="box" size="0.03 0.03 0.08"/></body>
    <body name="hand" pos="0.06 0 0.1" euler="0 0 90">
      <geom type="sphere" size="0.01" pos="0 -0.05 0" contype="0" conaffinity="0"/>
      <body name="finger" pos="0 0.02 0"><geom type="sphere" size="0.0105"/></body>
    </body>
  </worldbody>
</mujoco>)";
  char err[256] = "";
  mjVFS vfs;
  mj_defaultVFS(&vfs);
  ASSERT_EQ(mj_makeEmptyFileVFS(&vfs, "touch.xml", static_cast<int>(std::strlen(xml))), 0);
  std::memcpy(vfs.filedata[vfs.nfile - 1], xml, std::strlen(xml));
  std::unique_ptr<mjModel, void (*)(mjModel*)> m(mj_loadXML("touch.xml", &vfs, err, sizeof(err)),
                                                 mj_deleteModel);
  mj_deleteVFS(&vfs);
  ASSERT_NE(m, nullptr) << err;
  std::unique_ptr<mjData, void (*)(mjData*)> d(mj_makeData(m.get()), mj_deleteData);
  mj_forward(m.get(), d.get());
  const int hand = mj_name2id(m.get(), mjOBJ_BODY, "hand");
  const int box = mj_name2id(m.get(), mjOBJ_BODY, "box");
  const std::vector<bool> geoms = SubtreeGeoms(m.get(), hand);
  EXPECT_EQ(geoms, std::vector<bool>({false, true, true}));
  const std::vector<TouchContact> touch = HandTouch(m.get(), d.get(), geoms, hand, box);
  ASSERT_EQ(touch.size(), 1u);
  // world +x (out of the box's face) is the hand's -y; the contact, half way through the 0.5 mm
  // the finger sinks in, is at world x 0.02975: 0.03025 along the hand's +y
  EXPECT_LT((touch[0].normal - Eigen::Vector3d(0, -1, 0)).norm(), 1e-6);
  EXPECT_NEAR(touch[0].point.x(), 0.0, 1e-6);
  EXPECT_NEAR(touch[0].point.y(), 0.03025, 1e-4);
  EXPECT_NEAR(touch[0].point.z(), 0.0, 1e-6);
  EXPECT_TRUE(HandTouch(m.get(), d.get(), geoms, hand, -1).empty());
}

}  // namespace
}  // namespace simhuman::perceive
