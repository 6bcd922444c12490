// libFuzzer target: the config readers (control::MpcConfig::FromJson, learn::PpoConfig::FromJson
// and FromCheckpointJson) on arbitrary bytes parsed as JSON. A config that reads must validate
// and read back from its ToJson text unchanged.
// Built with -DSIMHUMAN_FUZZ=ON (clang); run by scripts/fuzz_smoke.sh.

#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string_view>

#include "simhuman/control/mpc/mpc_config.h"
#include "simhuman/core/json_io.h"
#include "simhuman/learn/ppo_config.h"

namespace {

// ToJson text, read again, must give the same ToJson
template <typename Config, typename Read>
void ExpectRoundTrip(const Config& c, Read read) {
  if (!c.Validate().ok()) std::abort();
  nlohmann::json written = c.ToJson();
  auto text = simhuman::core::ParseJson(written.dump(), "roundtrip.json");
  if (!text.ok()) std::abort();
  auto again = read(*text);
  if (!again.ok() || again->ToJson() != written) std::abort();
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  using namespace simhuman;
  std::string_view text(reinterpret_cast<const char*>(data), size);
  core::StatusOr<nlohmann::json> j = core::ParseJson(text, "fuzz.json");
  if (!j.ok()) return 0;
  auto mpc = control::MpcConfig::FromJson(*j, "fuzz.json");
  if (mpc.ok()) {
    ExpectRoundTrip(*mpc, [](const nlohmann::json& w) {
      return control::MpcConfig::FromJson(w, "roundtrip.json");
    });
  }
  auto ppo = learn::PpoConfig::FromJson(*j);
  if (ppo.ok()) {
    ExpectRoundTrip(*ppo, [](const nlohmann::json& w) { return learn::PpoConfig::FromJson(w); });
  }
  auto resumed = learn::PpoConfig::FromCheckpointJson(*j);
  if (resumed.ok() != ppo.ok()) std::abort();
  if (resumed.ok() && !j->contains("critic_hidden") && !resumed->critic_hidden.empty()) {
    std::abort();
  }
  return 0;
}
