// libFuzzer target: plan::ParseContactChain on arbitrary bytes; a chain that parses is grounded
// against a small catalog, and a grounded chain must survive a round trip through its JSON form.
// Built with -DSIMHUMAN_FUZZ=ON (clang); run by scripts/fuzz_smoke.sh.

#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string_view>

#include "simhuman/plan/contact_chain.h"
#include "simhuman/plan/test_scene.h"
#include "simhuman/plan/validate.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  using namespace simhuman;
  static const core::SceneCatalog scene = plan::fixtures::MakeTestScene();
  std::string_view text(reinterpret_cast<const char*>(data), size);
  absl::StatusOr<plan::ContactChain> chain = plan::ParseContactChain(text, "fuzz");
  if (!chain.ok()) return 0;
  if (!plan::ValidateAndGround(*chain, scene).ok()) return 0;
  // what the writer writes, the reader must read back and ground again
  std::string written = plan::ContactChainToJson(*chain).dump(
      -1, ' ', false, nlohmann::json::error_handler_t::replace);
  absl::StatusOr<plan::ContactChain> again = plan::ParseAndGround(written, "roundtrip", scene);
  if (!again.ok() || again->steps.size() != chain->steps.size()) std::abort();
  return 0;
}
