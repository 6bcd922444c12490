#include "simhuman/control/task.h"

#include <gtest/gtest.h>

#include <cmath>

#include "simhuman/plan/metrics.h"
#include "simhuman/world/objects.h"

namespace simhuman::control {
namespace {

core::CatalogObject Built(const std::string& type, double x, double y, double yaw_deg) {
  world::ObjectSpec spec;
  spec.id = type + "000";
  spec.type = type;
  spec.pos = Eigen::Vector3d(x, y, 0);
  spec.yaw_rad = yaw_deg * M_PI / 180.0;
  auto obj = world::BuildObject(spec);
  EXPECT_TRUE(obj.ok()) << obj.status();
  return *obj;
}

StepTask GetCloseFront(const core::CatalogObject& obj) {
  plan::PairParams params;
  StepTask t;
  t.get_close = true;
  t.focus = &obj;
  t.side = plan::Direction::kFront;
  t.stand_point = plan::StandPoint(obj, plan::Direction::kFront, params.stand_off_m);
  t.stand_yaw_rad = plan::StandFacingYaw(obj, plan::Direction::kFront);
  t.walk_point = t.stand_point;
  t.walk_yaw_rad = t.stand_yaw_rad;
  return t;
}

double AngleDiff(double a, double b) { return std::abs(std::remainder(a - b, 2 * M_PI)); }

TEST(RefineApproach, StopsBackToTheSeatBeforeSitting) {
  const core::CatalogObject chair = Built("chair", 1, 2, 30);
  StepTask gc = GetCloseFront(chair);
  StepTask sit;
  sit.focus = &chair;
  sit.posture = Posture::kSit;
  RefineApproach(sit, 1.0, &gc);
  EXPECT_NEAR(AngleDiff(gc.walk_yaw_rad, gc.stand_yaw_rad), M_PI, 1e-9);
  // in front of the chair (its +x), closer than the stand point, within the get-close radius
  Eigen::Vector3d local = chair.pose.ApplyInverse(gc.walk_point);
  EXPECT_NEAR(local.x(), chair.LocalBounds().second.x() + kSitStartM, 1e-9);
  EXPECT_LT((gc.walk_point - gc.stand_point).head<2>().norm(),
            plan::PairParams().get_close_radius_m);
}

TEST(RefineApproach, StopsBesideThePillowEndBeforeLyingDown) {
  const core::CatalogObject bed = Built("bed", 0, 0, 90);
  StepTask gc = GetCloseFront(bed);
  StepTask lie;
  lie.focus = &bed;
  lie.posture = Posture::kLieBack;
  RefineApproach(lie, 1.0, &gc);
  EXPECT_NEAR(AngleDiff(gc.walk_yaw_rad, gc.stand_yaw_rad), M_PI, 1e-9);
  const core::CatalogPart* pillow = bed.FindPart("pillow");
  ASSERT_NE(pillow, nullptr);
  auto [plo, phi] = core::ShapesBounds(pillow->shapes);
  Eigen::Vector3d local = bed.pose.ApplyInverse(gc.walk_point);
  EXPECT_NEAR(std::abs(local.y() - 0.5 * (plo.y() + phi.y())), kLieStartFromPillowM, 1e-9);
  EXPECT_LT((gc.walk_point - gc.stand_point).head<2>().norm(),
            plan::PairParams().get_close_radius_m);
}

TEST(RefineApproach, PutsAReachedPointAheadOfTheReachingShoulder) {
  world::ObjectSpec spec;
  spec.id = "marker000";
  spec.type = "marker";
  spec.pos = Eigen::Vector3d(2, 1, 1.2);
  spec.yaw_rad = 0.7;
  auto built = world::BuildObject(spec);
  ASSERT_TRUE(built.ok()) << built.status();
  const core::CatalogObject& marker = *built;
  for (core::BodyJoint hand : {core::BodyJoint::kLeftHand, core::BodyJoint::kRightHand}) {
    StepTask gc = GetCloseFront(marker);
    StepTask reach;
    reach.focus = &marker;
    ContactTerm t;
    t.joint = hand;
    t.type = plan::ContactType::kContact;
    t.object = &marker;
    t.part = &marker.parts.at(0);
    reach.terms.push_back(t);
    RefineApproach(reach, 1.0, &gc);
    EXPECT_EQ(gc.walk_yaw_rad, gc.stand_yaw_rad);  // still facing it
    Eigen::Vector2d fwd(std::cos(gc.walk_yaw_rad), std::sin(gc.walk_yaw_rad));
    Eigen::Vector2d lft(-fwd.y(), fwd.x());
    Eigen::Vector2d rel = marker.pose.pos.head<2>() - gc.walk_point.head<2>();
    EXPECT_NEAR(rel.dot(fwd), kReachAheadM, 0.03);  // the marker's radius
    double side = hand == core::BodyJoint::kLeftHand ? 1.0 : -1.0;
    EXPECT_NEAR(rel.dot(lft), side * kReachAcrossM, 1e-6);
    EXPECT_LT((gc.walk_point - gc.stand_point).head<2>().norm(),
              plan::PairParams().get_close_radius_m);
  }
}

TEST(RefineApproach, LeavesOtherStepsAlone) {
  const core::CatalogObject chair = Built("chair", 0, 0, 0);
  const core::CatalogObject sofa = Built("sofa", 3, 0, 0);
  StepTask gc = GetCloseFront(chair);
  StepTask sit_elsewhere;
  sit_elsewhere.focus = &sofa;
  sit_elsewhere.posture = Posture::kSit;
  RefineApproach(sit_elsewhere, 1.0, &gc);
  StepTask reach;
  reach.focus = &chair;
  reach.posture = Posture::kStand;
  RefineApproach(reach, 1.0, &gc);
  EXPECT_EQ(gc.walk_point, gc.stand_point);
  EXPECT_EQ(gc.walk_yaw_rad, gc.stand_yaw_rad);
}

// standing up from a seat or bed: the walk heading faces away from it (the way the human faces
// when it rises), the walk point stays; other steps before a get-close step change nothing
// a scene that starts the human seated on the chair: the first step's stand-up faces away from
// it; standing beside it, or seated elsewhere, changes nothing
TEST(RefineLeaving, AFirstStandUpFromWhereTheSceneSeatsTheHumanFacesAway) {
  const core::CatalogObject chair = Built("chair", 1, 2, 30);
  StepTask gc = GetCloseFront(chair);
  RefineLeavingFromStart(Eigen::Vector3d(1.0, 2.0, 0.55), 1.0, &gc);
  EXPECT_NEAR(AngleDiff(gc.walk_yaw_rad, gc.stand_yaw_rad), M_PI, 1e-9);
  for (const Eigen::Vector3d& pelvis : {Eigen::Vector3d(1.0, 2.0, 0.95),     // standing on it
                                        Eigen::Vector3d(3.0, 2.0, 0.55)}) {  // seated elsewhere
    StepTask other = GetCloseFront(chair);
    RefineLeavingFromStart(pelvis, 1.0, &other);
    EXPECT_EQ(other.walk_yaw_rad, other.stand_yaw_rad) << pelvis.transpose();
  }
}

TEST(RefineLeaving, StandingUpFromASeatFacesAwayFromIt) {
  const core::CatalogObject chair = Built("chair", 1, 2, 30);
  const core::CatalogObject sofa = Built("sofa", 4, 0, 0);
  for (Posture p : {Posture::kSit, Posture::kLieBack}) {
    StepTask gc = GetCloseFront(chair);
    StepTask seated;
    seated.focus = &chair;
    seated.posture = p;
    RefineLeaving(seated, &gc);
    EXPECT_NEAR(AngleDiff(gc.walk_yaw_rad, gc.stand_yaw_rad), M_PI, 1e-9);
    EXPECT_EQ(gc.walk_point, gc.stand_point);
  }
  StepTask gc = GetCloseFront(chair);
  StepTask standing;
  standing.focus = &chair;
  RefineLeaving(standing, &gc);
  StepTask on_sofa;
  on_sofa.focus = &sofa;
  on_sofa.posture = Posture::kSit;
  RefineLeaving(on_sofa, &gc);
  EXPECT_EQ(gc.walk_yaw_rad, gc.stand_yaw_rad);
}

}  // namespace
}  // namespace simhuman::control
