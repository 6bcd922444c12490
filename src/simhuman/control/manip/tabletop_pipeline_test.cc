#include "simhuman/control/manip/tabletop_pipeline.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>
#include <vector>

#include "simhuman/control/manip/scripted_grasp.h"
#include "simhuman/world/objects.h"
#include "simhuman/world/scene.h"
#include "simhuman/world/seating.h"
#include "simhuman/world/tabletop.h"

namespace simhuman::control::manip {
namespace {

struct Scene {
  std::unique_ptr<world::SimWorld> world;
  GraspIndex ix;
  TabletopGoal goal;
};

// the tabletop layout with one box to move and a place target 20 cm to its left
Scene BoxScene(double width, double mass) {
  world::SceneSpec spec = world::TabletopBaseScene("pipeline");
  world::ObjectSpec box;
  box.id = "box002";
  box.type = "box";
  box.color = "red";
  const Eigen::Vector3d base = world::TableToWorld(Eigen::Vector3d(0.0, 0.15, 0));
  box.pos = base;
  box.size = {{"depth", width}, {"width", width}, {"height", 0.15}};
  box.mass_kg = mass;
  box.friction = 1.0;
  spec.objects.push_back(box);
  auto catalog = world::BuildCatalog(spec);
  EXPECT_TRUE(catalog.ok()) << catalog.status();
  auto human = world::AgentFromHuman(spec.humans[0], 0, *catalog);
  world::ModelOptions opt;
  opt.timestep_s = 1.0 / 240;
  Scene s;
  s.world = std::move(*world::SimWorld::Create(*catalog, {*human}, opt));
  s.ix = *MakeGraspIndex(*s.world, 0, true);
  s.goal.object_body =
      mj_name2id(s.world->model(), mjOBJ_BODY, world::ObjectBodyName("box002").c_str());
  s.goal.shape = GraspShape::kBox;
  s.goal.half_width_m = width / 2;
  s.goal.height_m = 0.15;
  s.goal.planned_pos = base;
  s.goal.target = base + Eigen::Vector3d(0.0, 0.2, 0);
  return s;
}

// an object wider than the hand closes around ends the run before anything moves, named
TEST(TabletopPipelineTest, AnObjectTooWideForTheHandIsRefusedBeforeAnythingMoves) {
  Scene s = BoxScene(0.16, 2.0);
  const TabletopOptions o;
  const std::vector<double> qpos0(s.world->data()->qpos,
                                  s.world->data()->qpos + s.world->model()->nq);
  const TabletopResult r = RunTabletop(
      *s.world, s.ix, s.goal, [](const TabletopGoal&) { return GraspPolicyFn(); }, o);
  EXPECT_FALSE(r.success);
  EXPECT_FALSE(r.plan_failure);
  EXPECT_EQ(r.failed_stage, TabletopStage::kGrasp);
  EXPECT_EQ(r.end_reason,
            "too wide for the hand: box002 is 16.0 cm across where the hand would hold it; the "
            "hand closes around objects up to 12.0 cm");
  EXPECT_EQ(r.sim_steps, 0);
  for (int i = 0; i < s.world->model()->nq; ++i) EXPECT_EQ(s.world->data()->qpos[i], qpos0[i]);
}

// a fresh scripted grasp for each attempt
GraspPolicyFactory Scripted(const Scene& s, const TabletopOptions& options,
                            const ScriptedGraspOptions& grasp = {}) {
  return [&s, options, grasp](const TabletopGoal& g) {
    return MakeScriptedGrasp(s.world->model(), s.world->data(), s.ix, g, options, grasp);
  };
}

TEST(TabletopPipelineTest, EveryStageRunsAndReportsWhereItFailedIntegration) {
  Scene s = BoxScene(0.06, 1.0);
  const TabletopOptions options;
  TabletopResult r = RunTabletop(*s.world, s.ix, s.goal, Scripted(s, options), options);
  std::printf("result: %s (stage %s) steps %d wall %.2f s, final %.3f %.3f %.3f\n",
              r.end_reason.c_str(), TabletopStageName(r.failed_stage), r.sim_steps, r.wall_s,
              r.final_pos.x(), r.final_pos.y(), r.final_pos.z());
  EXPECT_GT(r.sim_steps, 100);
  EXPECT_FALSE(r.end_reason.empty());
  EXPECT_EQ(r.success, r.end_reason == "success");
  EXPECT_EQ(r.reach_route, "raised-onto");
}

// With the raise, the hand rises over the table's edge, then joins the reach planned from the
// hanging arm and arrives as it would have: the box is placed, and it stays where it stood
// until the hand is near (the way to the join keeps clear of it)
TEST(TabletopPipelineTest, TheRaisedHandJoinsTheReachFromTheHangingArmIntegration) {
  Scene s = BoxScene(0.06, 2.0);
  TabletopOptions options;
  options.raise_via_rad = SeatedRaiseViaRad();
  const Eigen::Vector3d box0(s.world->data()->xpos + 3 * s.goal.object_body);
  double moved_while_far = 0, nearest = 1e9;
  const StepHook hook = [&](const mjData* d) {
    const Eigen::Vector3d box(d->xpos + 3 * s.goal.object_body);
    const Eigen::Vector3d palm(d->site_xpos + 3 * s.ix.arm.palm_site);
    nearest = std::min(nearest, (palm - box).head<2>().norm());
    if (nearest > 0.1) moved_while_far = std::max(moved_while_far, (box - box0).norm());
  };
  const TabletopResult r = RunTabletop(*s.world, s.ix, s.goal, Scripted(s, options), options, hook);
  EXPECT_EQ(r.reach_route, "raised-onto");
  EXPECT_TRUE(r.success) << r.end_reason;
  EXPECT_LT(nearest, 0.1);
  EXPECT_LT(moved_while_far, 0.002);
}

// the scripted grasp picks a box up, carries it 20 cm and sets it down upright, at rest, for a
// light and a heavy box (this failed for every box before the grasp wrapped from the finger
// bases; it is a check on the grasp, the approach and the upright placing together)
TEST(TabletopPipelineTest, ScriptedGraspPlacesLightAndHeavyBoxesIntegration) {
  for (double mass : {1.0, 4.0}) {
    Scene s = BoxScene(0.06, mass);
    const TabletopOptions options;
    const TabletopResult r = RunTabletop(*s.world, s.ix, s.goal, Scripted(s, options), options);
    EXPECT_TRUE(r.success) << mass << " kg: " << r.end_reason;
    EXPECT_LT(std::hypot(r.final_pos.x() - s.goal.target.x(), r.final_pos.y() - s.goal.target.y()),
              0.10)
        << mass << " kg";
  }
}

// After a miss the hand lets go and tries again from where the object stands: a first attempt
// that keeps the hand open misses, the second (the scripted grasp) places the box. With one
// attempt allowed the same start ends at the miss.
TEST(TabletopPipelineTest, AMissedGraspIsTriedAgainIntegration) {
  for (int allowed : {1, 2}) {
    Scene s = BoxScene(0.06, 1.0);
    TabletopOptions options;
    options.grasp_attempts = allowed;
    int made = 0;
    const GraspPolicyFactory first_open = [&](const TabletopGoal& g) -> GraspPolicyFn {
      if (made++ == 0) {
        return [](const float*, float* act) { std::fill(act, act + kGraspActDim, 0.0f); };
      }
      return MakeScriptedGrasp(s.world->model(), s.world->data(), s.ix, g, options);
    };
    const TabletopResult r = RunTabletop(*s.world, s.ix, s.goal, first_open, options);
    std::printf("%d attempt(s) allowed: %s after %d\n", allowed, r.end_reason.c_str(),
                r.grasp_attempts);
    if (allowed == 1) {
      EXPECT_EQ(r.failed_stage, TabletopStage::kGrasp) << r.end_reason;
      EXPECT_EQ(r.grasp_attempts, 1);
    } else {
      EXPECT_TRUE(r.success) << r.end_reason;
      EXPECT_EQ(r.grasp_attempts, 2);
    }
  }
}

// A thin heavy box stays upright in the air: the hand keeps the rotation the reach gave it
// through the grasp, the lift and the transport. Before, the grasp's and the lift's IK took the
// hand's measured rotation as their target, so each push of the fingers and of the box's weight
// became the new target, and a 5 cm wide, 3 kg box turned 20-60 degrees on its way up (ep. 71 of
// the suite).
double LargestTiltInTheAir(bool hold_rotation) {
  Scene s = BoxScene(0.05, 3.0);
  const TabletopOptions options;
  ScriptedGraspOptions grasp;
  grasp.hold_rotation = hold_rotation;
  const int b = s.goal.object_body;
  const double z0 = s.world->data()->xipos[3 * b + 2];
  double tilt = 0;
  const TabletopResult r = RunTabletop(
      *s.world, s.ix, s.goal, Scripted(s, options, grasp), options, [&](const mjData* d) {
        if (d->xipos[3 * b + 2] > z0 + 0.05) {
          tilt = std::max(tilt, std::acos(std::clamp(d->xmat[9 * b + 8], -1.0, 1.0)));
        }
      });
  std::printf("hold_rotation %d: %s, largest tilt in the air %.1f deg\n", hold_rotation,
              r.end_reason.c_str(), tilt * 180 / M_PI);
  EXPECT_GT(tilt, 0) << "the box never rose";
  return tilt;
}

TEST(TabletopPipelineTest, AThinHeavyBoxStaysUprightInTheAirIntegration) {
  EXPECT_LT(LargestTiltInTheAir(true), 15 * M_PI / 180);
}

// The object reaches its support upright: the held box's load stays in the arm tracker's
// integral through the lift, the alignment and the descent. Reset at every straight move, the
// wrist sagged within each 3 cm descent segment and a 4 kg box met the table tilted by what the
// alignment had just taken out (6-14 degrees in the suite's stacks).
double ReleaseTilt(bool keep_load_integral) {
  Scene s = BoxScene(0.06, 4.0);
  TabletopOptions options;
  options.keep_load_integral = keep_load_integral;
  const TabletopResult r = RunTabletop(*s.world, s.ix, s.goal, Scripted(s, options), options);
  std::printf("keep_load_integral %d: %s, tilt at the release %.1f deg\n", keep_load_integral,
              r.end_reason.c_str(), r.release_tilt_deg);
  EXPECT_GE(r.release_tilt_deg, 0) << "the run ended before the release: " << r.end_reason;
  return r.release_tilt_deg;
}

TEST(TabletopPipelineTest, AHeavyBoxIsReleasedUprightIntegration) {
  const double kept = ReleaseTilt(true);
  EXPECT_LT(kept, 3.0);
  EXPECT_GT(ReleaseTilt(false), kept + 2.0);
}

}  // namespace
}  // namespace simhuman::control::manip
