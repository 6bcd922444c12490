#include "simhuman/control/mpc/getting_up.h"

#include <gtest/gtest.h>

#include <cmath>

#include "simhuman/control/mpc/mpc_controller.h"
#include "simhuman/control/runner.h"
#include "simhuman/plan/validate.h"
#include "simhuman/world/scene.h"

namespace simhuman::control {
namespace {

using J = core::BodyJoint;

struct Bedroom {
  core::SceneCatalog catalog;
  std::unique_ptr<world::SimWorld> world;
  plan::ContactChain chain;  // lie on the bed, then stand up in front of it
  StepTask lie, stand_up;
};

// the bedroom with its human where a lie-down starts (back to the bed's front edge)
Bedroom LieThenGetUp() {
  Bedroom b;
  auto spec = world::LoadScene("bedroom");
  EXPECT_TRUE(spec.ok()) << spec.status();
  auto cat = world::BuildCatalog(*spec);
  EXPECT_TRUE(cat.ok()) << cat.status();
  b.catalog = *cat;
  auto chain = plan::ParseAndGround(
      "[[[\"bed000\", \"none\", \"none\", \"none\", \"front\"]], "
      "[[\"bed000\", \"mattress\", \"pelvis\", \"contact\", \"up\"], "
      "[\"bed000\", \"pillow\", \"head\", \"contact\", \"up\"]], "
      "[[\"bed000\", \"none\", \"none\", \"none\", \"front\"]]]",
      "<test>", b.catalog);
  EXPECT_TRUE(chain.ok()) << chain.status();
  StepTask walk = BuildStepTask(chain->steps[0], b.catalog, 0, 1.0, plan::PairParams());
  b.lie = BuildStepTask(chain->steps[1], b.catalog, 0, 1.0, plan::PairParams());
  b.stand_up = BuildStepTask(chain->steps[2], b.catalog, 0, 1.0, plan::PairParams());
  RefineApproach(b.lie, 1.0, &walk);
  auto w = world::SimWorld::Create(b.catalog,
                                   {{walk.walk_point.x(), walk.walk_point.y(), walk.walk_yaw_rad}});
  EXPECT_TRUE(w.ok()) << w.status();
  b.world = std::move(w).value();
  b.chain.steps = {chain->steps[1], chain->steps[2]};
  return b;
}

std::array<Eigen::Vector3d, core::kNumBodyJoints> PointsOf(const world::SimWorld& w,
                                                           const ReferencePose& p, mjData* d) {
  SetAgentPose(w.agent(0), p, d);
  mj_kinematics(w.model(), d);
  return w.BodyPoints(d, 0);
}

double TrunkTiltDeg(const std::array<Eigen::Vector3d, core::kNumBodyJoints>& pts) {
  const Eigen::Vector3d up = pts[static_cast<int>(J::kHead)] - pts[static_cast<int>(J::kPelvis)];
  return std::acos(up.normalized().z()) * 180.0 / M_PI;
}

Eigen::Vector3d Hips(const std::array<Eigen::Vector3d, core::kNumBodyJoints>& pts) {
  return 0.5 * (pts[static_cast<int>(J::kLeftHip)] + pts[static_cast<int>(J::kRightHip)]);
}

// from the lie-down's pose on the bed: a curl (spine flexed, legs as they were), then the trunk
// upright over hips that stay where they were; nothing from a standing start
TEST(GettingUpTest, SitsUpThroughACurlWithTheHipsKeptIntegration) {
  Bedroom b = LieThenGetUp();
  const world::SimWorld& w = *b.world;
  mjData* d = mj_makeData(w.model());
  mjData* scratch = mj_makeData(w.model());
  mj_copyData(d, w.model(), w.data());
  EXPECT_TRUE(SitUpKeys(w, 0, d, scratch).empty()) << "standing";
  const ReferencePose lying = SolveReferencePose(w, 0, b.lie, w.data(), scratch);
  SetAgentPose(w.agent(0), lying, d);
  mj_kinematics(w.model(), d);
  const auto lying_pts = w.BodyPoints(d, 0);
  EXPECT_GT(TrunkTiltDeg(lying_pts), 75.0);
  const std::vector<ReferencePose> keys = SitUpKeys(w, 0, d, scratch);
  ASSERT_EQ(keys.size(), 2u);
  const auto curl = PointsOf(w, keys[0], scratch);
  const auto sat = PointsOf(w, keys[1], scratch);
  for (J j : {J::kLeftKnee, J::kRightKnee, J::kLeftFoot, J::kRightFoot}) {
    EXPECT_LT((curl[static_cast<int>(j)] - lying_pts[static_cast<int>(j)]).norm(), 1e-6);
    EXPECT_LT((sat[static_cast<int>(j)] - lying_pts[static_cast<int>(j)]).norm(), 0.01);
  }
  // the curl lifts the head, with the pelvis still down
  EXPECT_GT(curl[static_cast<int>(J::kHead)].z(), lying_pts[static_cast<int>(J::kHead)].z() + 0.2);
  EXPECT_LT((Hips(sat) - Hips(lying_pts)).norm(), 0.01);
  EXPECT_LT(TrunkTiltDeg(sat), 30.0);
  mj_deleteData(scratch);
  mj_deleteData(d);
}

// the edge-sit pose moves along the bed's front edge to where the pelvis lies, kept 0.2 m from
// the mattress's ends; its distance from the edge is unchanged
TEST(GettingUpTest, TheEdgeSitMovesAlongTheEdgeToThePelvisIntegration) {
  Bedroom b = LieThenGetUp();
  const world::SimWorld& w = *b.world;
  mjData* scratch = mj_makeData(w.model());
  std::optional<StepTask> sit = EdgeSitBeforeRising(b.stand_up, 1.0);
  ASSERT_TRUE(sit.has_value());
  EXPECT_EQ(sit->posture, Posture::kSit);
  EXPECT_FALSE(EdgeSitBeforeRising(b.lie, 1.0).has_value()) << "not a stand-up step";
  const ReferencePose edge = SolveReferencePose(w, 0, *sit, w.data(), scratch);
  const core::Pose& bed = b.catalog.objects[0].pose;
  auto [lo, hi] = core::ShapesBounds(b.catalog.objects[0].FindPart("mattress")->shapes);
  auto local = [&](const ReferencePose& p) {
    return bed.ApplyInverse(Eigen::Vector3d(p.root[0], p.root[1], p.root[2]));
  };
  for (double y : {lo.y() + 0.5, 0.5 * (lo.y() + hi.y()), hi.y() + 0.3}) {
    ReferencePose moved = edge;
    SitWhereLying(*sit, bed.Apply(Eigen::Vector3d(0.1, y, 0.6)), &moved);
    EXPECT_NEAR(local(moved).y(), std::min(y, hi.y() - 0.2), 1e-9);
    EXPECT_NEAR(local(moved).x(), local(edge).x(), 1e-9);
    EXPECT_NEAR(local(moved).z(), local(edge).z(), 1e-9);
  }
  mj_deleteData(scratch);
}

TEST(GettingUpTest, LegsHangDownStandingOrOnAnEdgeNotLying) {
  std::array<Eigen::Vector3d, core::kNumBodyJoints> pts;
  pts.fill(Eigen::Vector3d::Zero());
  auto set = [&](double pelvis_z, double feet_z) {
    pts[static_cast<int>(J::kPelvis)].z() = pelvis_z;
    pts[static_cast<int>(J::kLeftFoot)].z() = feet_z;
    pts[static_cast<int>(J::kRightFoot)].z() = feet_z;
  };
  set(0.95, 0.08);
  EXPECT_TRUE(LegsHangDown(pts, 1.0));  // standing
  set(0.62, 0.08);
  EXPECT_TRUE(LegsHangDown(pts, 1.0));  // on a bed's edge, feet on the floor
  set(0.62, 0.58);
  EXPECT_FALSE(LegsHangDown(pts, 1.0));  // lying or long-sitting
  pts[static_cast<int>(J::kLeftFoot)].z() = 0.08;
  EXPECT_FALSE(LegsHangDown(pts, 1.0));  // one leg over the edge
}

// the MPC alone lies down on the bed, then gets up through the bed's edge and stands in front
// of it (before: the hips flexed from flat on the back, the legs flew up and the human slid off
// the edge to the floor)
TEST(MpcControllerTest, GetsUpFromLyingOnABedThroughItsEdgeIntegration) {
  Bedroom b = LieThenGetUp();
  MpcConfig cfg = *MpcConfig::Preset("fast");
  auto ctl = MpcController::Create(b.world.get(), 0, cfg, 1);
  ASSERT_TRUE(ctl.ok()) << ctl.status();
  RunOptions ro;
  ro.record = false;
  ro.tracker.budget_s_per_step = 14;
  EpisodeResult r = RunEpisode(*b.world, b.chain, {ctl->get()}, ro, nullptr);
  EXPECT_GE(r.steps_completed, 1) << r.end_reason;
  EXPECT_FALSE(r.fell) << r.end_reason;
  const auto pts = b.world->BodyPoints(b.world->data(), 0);
  EXPECT_GT(pts[static_cast<int>(J::kPelvis)].z(), 0.8);
  EXPECT_LT(TrunkTiltDeg(pts), 20.0);
  EXPECT_TRUE(LegsHangDown(pts, 1.0));
}

}  // namespace
}  // namespace simhuman::control
