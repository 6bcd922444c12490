#include "simhuman/eval/sceneplan_levels.h"

#include <gtest/gtest.h>

#include <set>

#include "simhuman/core/rng.h"
#include "simhuman/eval/reachability.h"
#include "simhuman/plan/metrics.h"
#include "simhuman/plan/validate.h"
#include "simhuman/world/objects.h"

namespace simhuman::eval {
namespace {

constexpr int kSamples = 60;

struct Drawn {
  EpisodeSpec spec;
  plan::ContactChain chain;
  core::SceneCatalog catalog;
};

Drawn Draw(const std::string& suite, uint64_t seed) {
  Drawn d;
  core::StatusOr<EpisodeSpec> s = MakeEpisodeSpec(suite, seed);
  EXPECT_TRUE(s.ok()) << s.status();
  if (!s.ok()) return d;
  d.spec = *s;
  core::StatusOr<core::SceneCatalog> catalog = world::BuildCatalog(d.spec.scene);
  EXPECT_TRUE(catalog.ok()) << catalog.status();
  if (!catalog.ok()) return d;
  d.catalog = *catalog;
  core::StatusOr<plan::ContactChain> chain = plan::ParseContactChainJson(d.spec.plan, suite);
  EXPECT_TRUE(chain.ok()) << chain.status();
  if (!chain.ok()) return d;
  d.chain = *chain;
  EXPECT_TRUE(plan::ValidateAndGround(d.chain, d.catalog).ok()) << d.spec.plan.dump();
  EXPECT_TRUE(CheckWithinReach(d.chain, d.catalog, d.spec.scene.humans).ok()) << d.spec.plan.dump();
  return d;
}

// objects the plan's pairs name
std::set<std::string> Objects(const plan::ContactChain& chain) {
  std::set<std::string> out;
  for (const plan::ContactStep& step : chain.steps) {
    for (const plan::ContactPair& p : step.pairs) out.insert(p.object);
  }
  return out;
}

// the human starts 1-6 m from the first object's front stand point, in a furnished room
void ExpectRoomStart(const Drawn& d) {
  EXPECT_GE(d.spec.scene.objects.size(), 3u);
  const core::CatalogObject* first = d.catalog.Find(d.chain.steps[0].pairs[0].object);
  ASSERT_NE(first, nullptr);
  EXPECT_TRUE(d.chain.steps[0].pairs[0].IsGetClose());
  Eigen::Vector3d stand = plan::StandPoint(*first, plan::Direction::kFront, 0.45);
  double r = (d.spec.scene.humans.at(0).pos_xy - stand.head<2>()).norm();
  EXPECT_GE(r, 1.0 - 1e-9);
  EXPECT_LE(r, 6.0 + 1e-9);
}

TEST(ScenePlanLevelsTest, MediumPlansHaveMoreThanThreeStepsOnOneObject) {
  std::set<std::string> types;
  for (int i = 0; i < kSamples; ++i) {
    Drawn d = Draw("sceneplan-mid", core::DeriveSeed(21, i));
    ASSERT_FALSE(d.chain.steps.empty());
    EXPECT_GT(d.chain.steps.size(), 3u) << d.spec.plan.dump();
    EXPECT_EQ(Objects(d.chain).size(), 1u) << d.spec.plan.dump();
    types.insert(d.catalog.Find(*Objects(d.chain).begin())->type);
    ExpectRoomStart(d);
  }
  EXPECT_EQ(types, (std::set<std::string>{"chair", "armchair", "sofa", "bed"}));
}

TEST(ScenePlanLevelsTest, HardPlansUseSeveralObjectsAndTheLaptopWhileSeated) {
  for (int i = 0; i < kSamples; ++i) {
    Drawn d = Draw("sceneplan-hard", core::DeriveSeed(22, i));
    ASSERT_GT(d.chain.steps.size(), 3u);
    EXPECT_GE(Objects(d.chain).size(), 3u) << d.spec.plan.dump();  // chair, laptop, + one
    // one step holds the seat and both hands on the keyboard: two objects at once
    int two_objects = 0;
    for (const plan::ContactStep& step : d.chain.steps) {
      std::set<std::string> in_step;
      for (const plan::ContactPair& p : step.pairs) in_step.insert(p.object);
      two_objects += in_step.size() >= 2;
    }
    EXPECT_GE(two_objects, 1);
    ExpectRoomStart(d);
  }
}

TEST(ScenePlanLevelsTest, EpisodesAreAPureFunctionOfTheSeed) {
  for (const char* suite : {"sceneplan-mid", "sceneplan-hard"}) {
    core::StatusOr<EpisodeSpec> a = MakeEpisodeSpec(suite, 7), b = MakeEpisodeSpec(suite, 7);
    ASSERT_TRUE(a.ok() && b.ok());
    EXPECT_EQ(a->plan, b->plan);
    EXPECT_EQ(world::SceneToJson(a->scene), world::SceneToJson(b->scene));
    core::StatusOr<EpisodeSpec> c = MakeEpisodeSpec(suite, 8);
    ASSERT_TRUE(c.ok());
    EXPECT_NE(world::SceneToJson(a->scene), world::SceneToJson(c->scene));
  }
}

}  // namespace
}  // namespace simhuman::eval
