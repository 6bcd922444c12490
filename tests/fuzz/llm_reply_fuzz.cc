// libFuzzer target: the LLM planner's reply handling on arbitrary bytes: ExtractPlanJson(), then
// the strict plan parser and grounding that LlmPlanner applies to whatever it extracts.
// Built with -DSIMHUMAN_FUZZ=ON (clang); run by scripts/fuzz_smoke.sh.

#include <cstddef>
#include <cstdint>
#include <string_view>

#include "simhuman/language/reply_extract.h"
#include "simhuman/plan/contact_chain.h"
#include "simhuman/plan/test_scene.h"
#include "simhuman/plan/validate.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  using namespace simhuman;
  static const core::SceneCatalog scene = plan::fixtures::MakeTestScene();
  std::string_view reply(reinterpret_cast<const char*>(data), size);
  absl::StatusOr<nlohmann::json> json = language::ExtractPlanJson(reply);
  if (!json.ok()) {
    (void)language::Preview(reply);
    return 0;
  }
  absl::StatusOr<plan::ContactChain> chain = plan::ParseContactChainJson(*json, "llm reply");
  if (chain.ok()) (void)plan::ValidateAndGround(*chain, scene);
  return 0;
}
