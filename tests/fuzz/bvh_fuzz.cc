// libFuzzer target: learn::ParseBvh on arbitrary bytes; a file that parses is retargeted onto
// our humanoid (learn::RetargetBvh, which compiles the humanoid with MuJoCo), and a clip it
// returns must be valid and survive a round trip through the clip file form.
// Built with -DSIMHUMAN_FUZZ=ON (clang); run by scripts/fuzz_smoke.sh.

#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string>

#include "simhuman/learn/bvh.h"
#include "simhuman/learn/motion_clip.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  using namespace simhuman;
  std::string text(reinterpret_cast<const char*>(data), size);
  core::StatusOr<learn::BvhMotion> bvh = learn::ParseBvh(text, "fuzz.bvh");
  if (!bvh.ok()) return 0;
  if (bvh->frames.empty() || bvh->joints.empty()) std::abort();
  for (const auto& row : bvh->frames) {
    if (static_cast<int>(row.size()) != bvh->num_channels) std::abort();
  }
  core::StatusOr<learn::MotionClip> clip = learn::RetargetBvh(*bvh, "fuzz.bvh");
  if (!clip.ok()) return 0;
  if (!clip->Validate().ok() || clip->frames.size() != bvh->frames.size()) std::abort();
  core::StatusOr<learn::MotionClip> again =
      learn::ParseMotionClip(learn::MotionClipToJson(*clip), "roundtrip.clip.json");
  if (!again.ok() || again->frames.size() != clip->frames.size()) std::abort();
  return 0;
}
