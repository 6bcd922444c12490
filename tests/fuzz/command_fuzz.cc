// libFuzzer target: arbitrary bytes as a command to the offline planner, in a built-in scene.
// Any status is fine; a crash, a hang or an ungrounded plan is a bug.
// Build (clang): clang++ -fsanitize=fuzzer,address ... linking simhuman_language, simhuman_world.

#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string_view>

#include "simhuman/language/offline_planner.h"
#include "simhuman/plan/validate.h"
#include "simhuman/world/scene.h"

namespace {

struct Scenes {
  simhuman::core::SceneCatalog living_room;
  simhuman::core::SceneCatalog tabletop;
};

const Scenes& GetScenes() {
  static const Scenes* scenes = [] {
    auto* s = new Scenes;
    s->living_room = *simhuman::world::BuildCatalog(*simhuman::world::BuiltinScene("living_room"));
    s->tabletop = *simhuman::world::BuildCatalog(*simhuman::world::BuiltinScene("tabletop_demo"));
    return s;
  }();
  return *scenes;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const Scenes& scenes = GetScenes();
  // the first byte picks the scene and the start pose
  const bool tabletop = size > 0 && (data[0] & 1);
  simhuman::language::PlanContext context;
  context.scene = tabletop ? &scenes.tabletop : &scenes.living_room;
  context.agents.push_back({tabletop ? 0.2 : 4.0, tabletop ? 0.0 : -1.35, 0.0,
                            size > 0 && (data[0] & 2) ? "sit" : "stand"});
  std::string_view command(reinterpret_cast<const char*>(data), size);
  simhuman::language::OfflinePlanner planner;
  auto result = planner.Plan(command, context);
  if (result.ok()) {
    // every plan the planner returns must ground against its scene
    simhuman::plan::ContactChain chain = result->chain;
    if (!simhuman::plan::ValidateAndGround(chain, *context.scene).ok()) std::abort();
    if (result->explanation.size() != chain.steps.size()) std::abort();
  }
  return 0;
}
