// Placing from a kept state (RunTabletopToPlace, RunTabletopPlace) and the place policy's
// corrections: what the place training (learn/place_env.h) stands on.
#include <gtest/gtest.h>

#include <cmath>

#include "simhuman/control/manip/place_task.h"
#include "simhuman/control/manip/scripted_grasp.h"
#include "simhuman/control/manip/table_world.h"
#include "simhuman/control/manip/tabletop_pipeline.h"

namespace simhuman::control::manip {
namespace {

struct Table {
  TableWorld tw;
  GraspIndex ix;
  TabletopGoal goal;
  TabletopOptions options;
  GraspPolicyFactory grasp;
};

// a generated scene (DASH's ranges) ready to run; `seed` and `kind` as GenerateTabletop's
std::unique_ptr<Table> MakeTable(uint64_t seed, const std::string& kind) {
  auto t = std::make_unique<Table>();
  auto tw = MakeTableWorld(seed, kind);
  EXPECT_TRUE(tw.ok()) << tw.status();
  t->tw = std::move(*tw);
  t->ix = *MakeGraspIndex(*t->tw.world, 0, true);
  t->goal = *TabletopSceneGoal(t->tw.ts, *t->tw.world);
  Table* p = t.get();
  t->grasp = [p](const TabletopGoal& g) {
    return MakeScriptedGrasp(p->tw.world->model(), p->tw.world->data(), p->ix, g, p->options);
  };
  return t;
}

// the first generated scene of a box or cylinder whose pipeline reaches placing
std::unique_ptr<Table> TableThatReachesPlacing(const std::string& kind, PlaceStart* start,
                                               uint64_t* seed_out = nullptr) {
  for (uint64_t seed = 1; seed < 30; ++seed) {
    std::unique_ptr<Table> t = MakeTable(seed, kind);
    if (t->goal.shape == GraspShape::kSphere) continue;
    RunTabletopToPlace(*t->tw.world, t->ix, t->goal, t->grasp, t->options, start);
    if (seed_out) *seed_out = seed;
    if (start->ready()) return t;
  }
  ADD_FAILURE() << "no scene of seeds 1-29 reached placing";
  return nullptr;
}

// the whole run in one call and in two (up to placing, then placing from the kept state) end
// the same way, to the step; and placing runs again from the same state with the same result
TEST(PlaceStartTest, PlacingFromAKeptStateRepeatsTheWholeRunIntegration) {
  PlaceStart start;
  uint64_t seed = 0;
  std::unique_ptr<Table> split = TableThatReachesPlacing("stack", &start, &seed);
  ASSERT_NE(split, nullptr);
  const TabletopResult second =
      RunTabletopPlace(*split->tw.world, split->ix, start, split->options);
  const TabletopResult again = RunTabletopPlace(*split->tw.world, split->ix, start, split->options);

  std::unique_ptr<Table> whole = MakeTable(seed, "stack");
  const TabletopResult one =
      RunTabletop(*whole->tw.world, whole->ix, whole->goal, whole->grasp, whole->options);
  EXPECT_EQ(one.end_reason, second.end_reason);
  EXPECT_EQ(one.sim_steps, second.sim_steps);
  EXPECT_NEAR((one.final_pos - second.final_pos).norm(), 0, 1e-9);
  EXPECT_EQ(again.sim_steps, second.sim_steps);
  EXPECT_NEAR((again.final_pos - second.final_pos).norm(), 0, 1e-9);
  EXPECT_GT(start.steps, 0);
  EXPECT_LT(start.steps, second.sim_steps);
}

// a place policy is asked before each descent segment; a zero action is the scripted placing,
// a large aim offset moves where the object lands
TEST(PlaceStartTest, APlacePolicyCorrectsTheScriptedPlacingIntegration) {
  PlaceStart start;
  std::unique_ptr<Table> t = TableThatReachesPlacing("place", &start);
  ASSERT_NE(t, nullptr);
  const TabletopResult scripted = RunTabletopPlace(*t->tw.world, t->ix, start, t->options);
  int asked = 0;
  const PlacePolicyFn zero = [&](const float* obs, float* act) {
    for (int i = 0; i < kPlaceObsDim; ++i) EXPECT_TRUE(std::isfinite(obs[i])) << i;
    for (int i = 0; i < kPlaceActDim; ++i) act[i] = 0;
    ++asked;
  };
  const TabletopResult zeroed = RunTabletopPlace(*t->tw.world, t->ix, start, t->options, zero);
  EXPECT_GE(asked, 1);
  EXPECT_LE(asked, 4);  // 10 cm of descent in 3 cm segments
  EXPECT_EQ(zeroed.sim_steps, scripted.sim_steps);
  EXPECT_NEAR((zeroed.final_pos - scripted.final_pos).norm(), 0, 1e-9);

  const PlacePolicyFn aside = [](const float*, float* act) {
    for (int i = 0; i < kPlaceActDim; ++i) act[i] = 0;
    act[0] = 1;  // aim 1.5 cm further along +x
  };
  const TabletopResult moved = RunTabletopPlace(*t->tw.world, t->ix, start, t->options, aside);
  EXPECT_GT(moved.final_pos.x() - scripted.final_pos.x(), 0.007)
      << scripted.end_reason << " / " << moved.end_reason;

  const TabletopResult none = RunTabletopPlace(*t->tw.world, t->ix, PlaceStart(), t->options);
  EXPECT_FALSE(none.success);
  EXPECT_NE(none.end_reason.find("no state where placing begins"), std::string::npos);
}

TEST(PlaceStartTest, ActionsMapToBoundedCorrections) {
  const float big[kPlaceActDim] = {5, -5, 1, -1, NAN};
  const PlaceAdjust a = PlaceAdjustFromAction(big);
  EXPECT_DOUBLE_EQ(a.aim.x(), kPlaceAimScaleM);
  EXPECT_DOUBLE_EQ(a.aim.y(), -kPlaceAimScaleM);
  EXPECT_DOUBLE_EQ(a.speed_scale, 1.0);  // non-finite reads as 0
  const Eigen::Vector3d up = PlaceUpGoal(a);
  EXPECT_NEAR(up.norm(), 1, 1e-12);
  EXPECT_NEAR(std::acos(up.z()), std::hypot(kPlaceTiltScaleRad, kPlaceTiltScaleRad), 1e-3);
  EXPECT_EQ(PlaceUpGoal(PlaceAdjust()), Eigen::Vector3d::UnitZ());
}

}  // namespace
}  // namespace simhuman::control::manip
