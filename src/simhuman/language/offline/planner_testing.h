#pragma once
/// Tests only (the language module's test binary links simhuman_world): a built-in scene loaded
/// as the offline planner sees it, and a plan written compactly.

#include <string>

#include "simhuman/language/offline_planner.h"
#include "simhuman/world/scene.h"

namespace simhuman::language::testing {

struct SceneFixture {
  world::SceneSpec spec;
  core::SceneCatalog catalog;
  PlanContext context;
};

/// The built-in scene `scene` with its humans as the planner's agents.
inline SceneFixture LoadScene(const std::string& scene) {
  SceneFixture f;
  f.spec = *world::LoadScene(scene);
  f.catalog = *world::BuildCatalog(f.spec);
  f.context.scene = &f.catalog;
  for (const world::HumanSpec& h : f.spec.humans) {
    f.context.agents.push_back({h.pos_xy.x(), h.pos_xy.y(), h.yaw_rad, h.posture});
  }
  return f;
}

/// The offline planner's answer in `scene`: "object:part:joint" per pair, steps separated by
/// " / "; "error: ..." when refused.
inline std::string PlanPairs(const std::string& scene, const std::string& command) {
  SceneFixture f = LoadScene(scene);
  OfflinePlanner planner;
  core::StatusOr<PlanResult> r = planner.Plan(command, f.context);
  if (!r.ok()) return "error: " + std::string(r.status().message());
  std::string out;
  for (const plan::ContactStep& s : r->chain.steps) {
    if (!out.empty()) out += " / ";
    std::string step;
    for (const plan::ContactPair& p : s.pairs) {
      if (!step.empty()) step += ", ";
      step += p.object + ":" + p.part + ":" +
              (p.joint ? std::string(core::BodyJointName(*p.joint)) : "none");
    }
    out += step;
  }
  return out;
}

}  // namespace simhuman::language::testing
