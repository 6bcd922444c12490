// libFuzzer target: world::ParseSceneJson on arbitrary bytes parsed as JSON, in both of its forms
// (ours and a UniHSI ScenePlan entry, bare or wrapped). A scene that parses must build its
// catalog, and what SceneToJson writes for it (the scene.json of a run) must load again as the
// same scene. Built with -DSIMHUMAN_FUZZ=ON (clang); run by scripts/fuzz_smoke.sh.

#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string_view>

#include "simhuman/core/json_io.h"
#include "simhuman/world/scene.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  using namespace simhuman;
  std::string_view text(reinterpret_cast<const char*>(data), size);
  core::StatusOr<nlohmann::json> j = core::ParseJson(text, "fuzz.json");
  if (!j.ok()) return 0;
  core::StatusOr<world::SceneSpec> spec = world::ParseSceneJson(*j, "fuzz.json");
  if (!spec.ok()) return 0;
  if (spec->humans.empty()) std::abort();  // a default human is always added
  core::StatusOr<core::SceneCatalog> catalog = world::BuildCatalog(*spec);
  if (!catalog.ok() || catalog->objects.size() != spec->objects.size()) std::abort();
  // the written form loads again, with the same objects and humans
  core::StatusOr<world::SceneSpec> again =
      world::ParseSceneJson(world::SceneToJson(*spec), "roundtrip.json");
  if (!again.ok() || again->objects.size() != spec->objects.size() ||
      again->humans.size() != spec->humans.size()) {
    std::abort();
  }
  for (size_t i = 0; i < spec->objects.size(); ++i) {
    if (again->objects[i].id != spec->objects[i].id) std::abort();
  }
  return 0;
}
