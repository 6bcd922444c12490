#include "simhuman/language/offline_planner.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "simhuman/world/scene.h"

namespace simhuman::language {
namespace {

using ::testing::HasSubstr;

struct Fixture {
  world::SceneSpec spec;
  core::SceneCatalog catalog;
  PlanContext context;
};

Fixture Load(const std::string& scene) {
  Fixture f;
  f.spec = *world::LoadScene(scene);
  f.catalog = *world::BuildCatalog(f.spec);
  f.context.scene = &f.catalog;
  for (const world::HumanSpec& h : f.spec.humans) {
    f.context.agents.push_back({h.pos_xy.x(), h.pos_xy.y(), h.yaw_rad, h.posture});
  }
  return f;
}

// "object|part|joint|contact|direction" per pair, steps separated by " / "
std::string Compact(const plan::ContactChain& chain) {
  std::string out;
  for (const plan::ContactStep& s : chain.steps) {
    if (!out.empty()) out += " / ";
    std::string step;
    for (const plan::ContactPair& p : s.pairs) {
      if (!step.empty()) step += ", ";
      std::string joint = p.subject_object ? "@" + *p.subject_object + ":" + p.subject_part
                          : p.joint      ? std::string(core::BodyJointName(*p.joint))
                                         : "none";
      step += p.object + "|" + p.part + "|" + joint + "|" +
              (p.IsGetClose() ? "none" : std::string(plan::ContactTypeName(p.type))) + "|" +
              std::string(plan::DirectionName(p.direction));
    }
    out += step;
  }
  return out;
}

std::string PlanText(const std::string& scene, const std::string& command) {
  Fixture f = Load(scene);
  OfflinePlanner planner;
  core::StatusOr<PlanResult> r = planner.Plan(command, f.context);
  if (!r.ok()) return "ERROR " + std::string(r.status().ToString());
  EXPECT_EQ(r->explanation.size(), r->chain.steps.size());
  return Compact(r->chain);
}

TEST(OfflinePlannerTest, SitOnTheChairInSitDemo) {
  EXPECT_EQ(PlanText("sit_demo", "sit on the chair"), "chair000|seat surface|pelvis|contact|up");
}

TEST(OfflinePlannerTest, Name) { EXPECT_EQ(OfflinePlanner().name(), "offline"); }

}  // namespace
}  // namespace simhuman::language
